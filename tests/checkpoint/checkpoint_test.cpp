// Checkpoints in code (scene/checkpoint.h): every example scene and every scene of the fuzz corpus
// written as JSON reads back equal; a scene with every key away from its default too (a key the
// writer forgot fails); a session saved and restored into a new session steps on with the same
// bits; a checkpoint whose bytes are changed anywhere is refused, naming the file.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "core/errors.h"
#include "core/sealed_file.h"
#include "scene/checkpoint.h"
#include "scene/scene.h"
#include "scene/scene_json.h"
#include "scene/session_spec.h"
#include "sim/diagnostics.h"

namespace pond::scene {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(SceneJson, EveryExampleAndCorpusSceneReadsBackEqual) {
  int scenes = 0;
  for (const fs::path& dir : {fs::path(POND_SCENES_DIR), fs::path(POND_FUZZ_DIR) / "corpus/scene"})
    for (const auto& e : fs::directory_iterator(dir)) {
      if (e.path().extension() != ".json") continue;
      Scene s;
      try {
        s = parse_scene(read(e.path()), e.path().string());
      } catch (const InputError&) {
        continue;  // a corpus entry may be bad input on purpose
      }
      ++scenes;
      EXPECT_EQ(parse_scene(scene_json(s), "again"), s) << e.path();
    }
  EXPECT_GT(scenes, 10);
}

TEST(SceneJson, EveryKeyAwayFromItsDefaultReadsBack) {
  // Each value differs from the parser's default, so a key the writer leaves out reads back as its
  // default and the comparison fails.
  const Scene s = parse_scene(R"({
    "name": "all keys", "grid": {"rows": 21, "cols": 23, "spacing": 0.75},
    "physics": {"mass": 3.5, "stiffness": 6.5, "damping": 0.07, "dt": 0.3, "substeps": 2, "rest_ratio": 0.95,
                "gravity": 0.06, "water_density": 1.1, "body_drag": 0.04},
    "border": "vertical",
    "constraints": [{"kind": "fixed", "rows": [8, 10], "cols": [11, 13]}, {"kind": "vertical", "rows": [1, 2], "cols": [3, 4]}],
    "perturbations": [{"step": 4, "row": 5.25, "col": 6.5, "radius": 1.5, "amplitude": -0.3, "target": "position", "mode": "set"}],
    "basin": {"floor_depth": 3.5, "land_height": 0.8},
    "bodies": [{"motion": "floating", "radius": 1.5, "mass": 7.25, "position": [4, 1, 4], "velocity": [0.01, 0, -0.02]},
               {"motion": "floating", "radius": 1.0, "density": 0.4, "position": [12, 1, 3]},
               {"motion": "kinematic", "radius": 1.2, "path": [[0, 3, 0.2, 12], [50, 9, -0.1, 12]]}],
    "view": {"steps_per_frame": 3, "lod_tolerance": 2.5, "reflections": false, "caustics": false, "shadows": false, "submerged": false},
    "camera": {"eye": [1, 9, -4], "target": [8, 0, 7], "fovy": 50},
    "lighting": {"sun": [0.2, 0.9, 0.1], "water": [0.1, 0.2, 0.3], "absorption": [0.4, 0.5, 0.6], "sky": [0.3, 0.4, 0.5], "ground": [0.6, 0.5, 0.4]},
    "tree": {"depth": 4, "seed": 9, "height": 5, "positions": [[9, 12], [2.5, 3.5]], "bend": "keep-length", "draw": "lines", "leaves": false},
    "wind": {"strength": 7, "direction_deg": 30, "seed": 4, "ripples": true}})",
                              "all keys");
  EXPECT_EQ(parse_scene(scene_json(s), "again"), s);
}

Scene busy() { return load_scene(POND_SCENES_DIR "/../tests/checkpoint/busy_scene.json"); }

const sim::SolverChoice kScalar{.gpu = false, .backend = sim::Backend::scalar, .threads = 1};

TEST(Checkpoint, ASavedSessionGoesOnWithTheSameBits) {
  const Scene scene = busy();
  sim::Session straight(session_spec(scene), kScalar);
  straight.advance(90);
  straight.set_wind_strength(8);
  straight.advance_wind(1.25);
  straight.rain(3.0, 0.8, -0.5);
  straight.advance(60);

  sim::Session first(session_spec(scene), kScalar);
  first.advance(90);
  first.set_wind_strength(8);
  first.advance_wind(1.25);
  const fs::path file = fs::path(::testing::TempDir()) / "saved.ckpt";
  write_checkpoint(file, scene, first, first.image());
  const Checkpoint back = read_checkpoint(file);
  std::unique_ptr<sim::Session> second = resume_session(back, kScalar, {});
  EXPECT_EQ(second->steps_done(), 90);
  second->rain(3.0, 0.8, -0.5);  // the rain's generator goes on where it was
  second->advance(60);
  EXPECT_EQ(sim::state_hash(second->state(), second->model()), sim::state_hash(straight.state(), straight.model()));
  EXPECT_EQ(second->wind().time(), straight.wind().time());
  EXPECT_EQ(second->wind().spec().strength, 8.0);
  EXPECT_EQ(second->wind().frame(0, tree::BendMode::article).wind.x, straight.wind().frame(0, tree::BendMode::article).wind.x);
}

TEST(Checkpoint, EditsMadeAtRunTimeAreInTheScene) {
  const Scene scene = busy();
  sim::Session s(session_spec(scene), kScalar);
  s.advance(10);
  sim::Physics p = s.water().physics;
  p.damping = 0.11;
  s.set_physics(p);
  s.set_sun({0.1, 0.8, 0.3});
  s.remove_body(0);
  const fs::path file = fs::path(::testing::TempDir()) / "edited.ckpt";
  write_checkpoint(file, scene, s, s.image());
  const Checkpoint back = read_checkpoint(file);
  EXPECT_EQ(back.scene.physics.damping, 0.11);
  EXPECT_EQ(back.scene.lighting.sun, (std::array<double, 3>{0.1, 0.8, 0.3}));
  EXPECT_EQ(back.scene.bodies.size(), scene.bodies.size() - 1);
  EXPECT_EQ(back.scene.camera, scene.camera);
}

TEST(Checkpoint, AnyChangedByteIsRefusedNamingTheFile) {
  const Scene scene = busy();
  sim::Session s(session_spec(scene), kScalar);
  s.advance(5);
  const fs::path file = fs::path(::testing::TempDir()) / "whole.ckpt";
  write_checkpoint(file, scene, s, s.image());
  const std::string bytes = read(file);
  ASSERT_NO_THROW(decode_checkpoint(bytes, "whole.ckpt"));
  // Every byte of the header and a spread of the payload, each changed alone; then truncations.
  for (std::size_t at = 0; at < bytes.size(); at += at < 64 ? 1 : 97) {
    std::string changed = bytes;
    changed[at] = static_cast<char>(changed[at] ^ 0x20);
    try {
      decode_checkpoint(changed, "c.ckpt");
      ADD_FAILURE() << "byte " << at << " changed and accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("'c.ckpt'"), std::string::npos) << e.what();
    }
  }
  for (std::size_t keep : {std::size_t{0}, std::size_t{7}, std::size_t{40}, bytes.size() / 2, bytes.size() - 1})
    EXPECT_THROW(decode_checkpoint(bytes.substr(0, keep), "t.ckpt"), InputError) << keep << " bytes";
}

TEST(Checkpoint, ASealedPayloadThatLiesIsRefused) {
  // Payloads with a good seal but bad contents (what a fuzzer reaches past the checksum): a JSON
  // part longer than the payload, not JSON, without a session, a state of another size, a body too
  // many, bytes after the bodies. Each is refused as bad input naming the file.
  const Scene scene = busy();
  sim::Session s(session_spec(scene), kScalar);
  const fs::path file = fs::path(::testing::TempDir()) / "good.ckpt";
  write_checkpoint(file, scene, s, s.image());
  const std::string good = unseal(read(file), checkpoint_format(), "good");
  std::uint64_t json_bytes;
  std::memcpy(&json_bytes, good.data(), 8);
  const std::string json = good.substr(8, json_bytes), rest = good.substr(8 + json_bytes);
  auto with_length = [](std::uint64_t n) { return std::string(reinterpret_cast<const char*>(&n), 8); };
  const std::string lies[] = {
      std::string(),
      with_length(1u << 30) + json,
      with_length(5) + "nope!" + rest,
      with_length(2) + "{}" + rest,
      with_length(json.size()) + json + rest.substr(0, rest.size() - 4),
      with_length(json.size()) + json + rest + "x",
      with_length(json.size()) + json + with_length(3) + rest.substr(8),
  };
  for (const std::string& payload : lies) {
    const std::vector<std::byte> sealed = seal_checkpoint(std::as_bytes(std::span(payload.data(), payload.size())));
    try {
      decode_checkpoint(std::string_view(reinterpret_cast<const char*>(sealed.data()), sealed.size()), "lie.ckpt");
      ADD_FAILURE() << "a lying payload of " << payload.size() << " bytes was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("lie.ckpt"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace pond::scene
