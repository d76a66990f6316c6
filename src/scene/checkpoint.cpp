#include "scene/checkpoint.h"

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/errors.h"
#include "core/output_file.h"
#include "core/sealed_file.h"
#include "scene/scene_json.h"
#include "scene/session_spec.h"

namespace pond::scene {
namespace {

using nlohmann::json;

static_assert(sizeof(sim::BodyState) == 28, "the checkpoint's layout names a body of 28 bytes");
static_assert(sizeof(float) == 4);

// What the payload holds, in order; its hash is the file's layout (a change here refuses old files).
constexpr std::string_view kLayout =
    "u64 json bytes; json {scene: the scene file's keys, session: {steps, ripples_until, clamp_reported, "
    "rain: {engine: mt19937 text, carry}, wind: {user: [strength, direction, units_per_strength], strength, "
    "direction_deg, time, states: [[time, phase, wind x, wind z]]}}}; u64 rows; u64 cols; "
    "f32[rows*cols] ux, uy, uz, vx, vy, vz row-major in grid units; u64 bodies; "
    "body {f32 x, y, z, vx, vy, vz in grid units; u32 flags}";

const SealedFormat kFormat{.magic = "PONDCKPT", .version = 1, .layout = layout_hash(kLayout), .kind = "a pond checkpoint"};

template <class T>
void put(std::vector<std::byte>& out, const T* values, std::size_t count) {
  const auto* p = reinterpret_cast<const std::byte*>(values);
  out.insert(out.end(), p, p + count * sizeof(T));
}
void put_u64(std::vector<std::byte>& out, std::uint64_t v) { put(out, &v, 1); }

json session_json(const sim::SessionImage& image) {
  const tree::Wind::Image& w = image.wind;
  json states = json::array();
  for (const tree::WindState& s : w.states) states.push_back({s.time, s.phase, s.wind.x, s.wind.z});
  return {{"steps", image.steps},
          {"ripples_until", image.ripples_until},
          {"clamp_reported", image.clamp_reported},
          {"rain", {{"engine", image.rain.engine}, {"carry", image.rain.carry}}},
          {"wind",
           {{"user", {w.user.strength, w.user.direction, w.user.units_per_strength}},
            {"strength", w.strength},
            {"direction_deg", w.direction_deg},
            {"time", w.time},
            {"states", std::move(states)}}}};
}

// Reads the payload front to back; every shortfall is the file's fault.
class Reader {
 public:
  Reader(std::string_view bytes, std::string name) : bytes_(bytes), name_(std::move(name)) {}
  [[noreturn]] void fail(const std::string& what) const { throw InputError("'" + name_ + "' " + what); }
  std::string_view take(std::uint64_t n, const char* what) {
    if (n > bytes_.size() - at_) fail(std::string("ends inside its ") + what);
    const auto size = static_cast<std::size_t>(n);  // fits: it is at most the bytes left
    const std::string_view out = bytes_.substr(at_, size);
    at_ += size;
    return out;
  }
  std::uint64_t u64(const char* what) {
    std::uint64_t v;
    std::memcpy(&v, take(8, what).data(), 8);
    return v;
  }
  bool done() const { return at_ == bytes_.size(); }

 private:
  std::string_view bytes_;
  std::string name_;
  std::size_t at_ = 0;
};

// session.<key> as a T (an integer, a finite number or a string), or the file's fault naming it.
template <class T>
T field(const json& j, const char* key, const Reader& r, const std::string& path) {
  const auto it = j.find(key);
  if (it == j.end()) r.fail("lacks session." + path + key);
  bool ok = false;
  if constexpr (std::is_same_v<T, std::string>) ok = it->is_string();
  else if constexpr (std::is_floating_point_v<T>) ok = it->is_number() && std::isfinite(it->get<double>());
  else if constexpr (std::is_unsigned_v<T>) ok = it->is_number_unsigned();
  else ok = it->is_number_integer();
  if (!ok) r.fail("has a session." + path + key + " of the wrong type");
  return it->get<T>();
}

tree::Wind::Image wind_image(const json& w, const Reader& r) {
  if (!w.is_object()) r.fail("has a session.wind that is not an object");
  tree::Wind::Image out;
  const json user = w.value("user", json());
  if (!user.is_array() || user.size() != 3 || !user[0].is_number() || !user[1].is_number() || !user[2].is_number())
    r.fail("has a session.wind.user that is not three numbers");
  out.user = {user[0].get<float>(), user[1].get<float>(), user[2].get<float>()};
  out.strength = field<double>(w, "strength", r, "wind.");
  out.direction_deg = field<double>(w, "direction_deg", r, "wind.");
  out.time = field<double>(w, "time", r, "wind.");
  const json states = w.value("states", json());
  if (!states.is_array()) r.fail("has a session.wind.states that is not an array");
  for (const json& s : states) {
    if (!s.is_array() || s.size() != 4) r.fail("has a session.wind.states entry that is not four numbers");
    for (const json& v : s)
      if (!v.is_number() || !std::isfinite(v.get<double>())) r.fail("has a session.wind.states entry that is not four numbers");
    out.states.push_back({s[0].get<double>(), s[1].get<double>(), {s[2].get<float>(), s[3].get<float>()}});
  }
  return out;
}

}  // namespace

const SealedFormat& checkpoint_format() { return kFormat; }
std::vector<std::byte> seal_checkpoint(std::span<const std::byte> payload) { return seal(kFormat, payload); }

void write_checkpoint(const std::filesystem::path& path, const Scene& scene, const sim::Session& session,
                      const sim::SessionImage& image) {
  Scene saved = scene;
  static_cast<sim::WaterSpec&>(saved) = image.water;
  saved.lighting.sun = session.sun();
  saved.wind = session.ripples_spec();
  const std::string text = json{{"scene", scene_to_json(saved)}, {"session", session_json(image)}}.dump();
  std::vector<std::byte> payload;
  put_u64(payload, text.size());
  put(payload, text.data(), text.size());
  const sim::WaterState& s = image.state;
  put_u64(payload, static_cast<std::uint64_t>(saved.grid.rows));
  put_u64(payload, static_cast<std::uint64_t>(saved.grid.cols));
  for (const auto* c : {&s.ux, &s.uy, &s.uz, &s.vx, &s.vy, &s.vz}) put(payload, c->data(), c->size());
  put_u64(payload, s.bodies.size());
  put(payload, s.bodies.data(), s.bodies.size());
  write_sealed(path, kFormat, payload);
}

Checkpoint decode_checkpoint(std::string_view bytes, const std::string& name) {
  const std::string payload = unseal(bytes, kFormat, name);
  Reader r(payload, name);
  const std::uint64_t text_bytes = r.u64("JSON part");
  const std::string_view text = r.take(text_bytes, "JSON part");
  json root;
  try {
    root = json::parse(text);
  } catch (const json::exception&) {
    r.fail("has a JSON part that does not parse");
  }
  if (!root.is_object() || !root.contains("scene") || !root.contains("session") || !root["session"].is_object())
    r.fail("lacks its scene or its session");
  Checkpoint out;
  out.scene = parse_scene(root["scene"].dump(), name + " (its scene)", ParseOptions{.body_overlaps = false});
  const json& sj = root["session"];
  sim::SessionImage& image = out.image;
  image.water = out.scene;
  image.steps = field<std::int64_t>(sj, "steps", r, "");
  image.ripples_until = field<std::int64_t>(sj, "ripples_until", r, "");
  if (image.steps < 0 || image.ripples_until < 0) r.fail("has a negative step count");
  image.clamp_reported = field<std::uint64_t>(sj, "clamp_reported", r, "");
  const json rain = sj.value("rain", json());
  if (!rain.is_object()) r.fail("lacks session.rain");
  image.rain = {field<std::string>(rain, "engine", r, "rain."), field<double>(rain, "carry", r, "rain.")};
  image.wind = wind_image(sj.value("wind", json()), r);

  const std::uint64_t rows = r.u64("grid"), cols = r.u64("grid");
  if (rows != static_cast<std::uint64_t>(out.scene.grid.rows) || cols != static_cast<std::uint64_t>(out.scene.grid.cols))
    r.fail("holds a " + std::to_string(rows) + " x " + std::to_string(cols) + " state for its " +
           std::to_string(out.scene.grid.rows) + " x " + std::to_string(out.scene.grid.cols) + " scene");
  const std::size_t nodes = static_cast<std::size_t>(rows * cols);
  sim::WaterState& s = image.state;
  s = sim::WaterState(nodes);
  for (auto* c : {&s.ux, &s.uy, &s.uz, &s.vx, &s.vy, &s.vz}) {
    std::memcpy(c->data(), r.take(nodes * sizeof(float), "state").data(), nodes * sizeof(float));
    for (std::size_t n = 0; n < nodes; ++n)
      if (!std::isfinite((*c)[n]))
        r.fail("holds a value that is not finite at node (" + std::to_string(n / cols) + ", " +
               std::to_string(n % cols) + ")");
  }
  const std::uint64_t bodies = r.u64("bodies");
  if (bodies != out.scene.bodies.size())
    r.fail("holds " + std::to_string(bodies) + " bodies for its scene's " + std::to_string(out.scene.bodies.size()));
  s.bodies.resize(out.scene.bodies.size());
  const auto body_bytes = r.take(bodies * sizeof(sim::BodyState), "bodies");
  if (bodies != 0) std::memcpy(s.bodies.data(), body_bytes.data(), body_bytes.size());
  for (const sim::BodyState& b : s.bodies)
    for (float v : {b.x, b.y, b.z, b.vx, b.vy, b.vz})
      if (!std::isfinite(v)) r.fail("holds a body whose state is not finite");
  if (!r.done()) r.fail("has bytes after its bodies");
  return out;
}

Checkpoint read_checkpoint(const std::filesystem::path& path) {
  return decode_checkpoint(read_file(path), path.string());
}

std::unique_ptr<sim::Session> resume_session(const Checkpoint& checkpoint, sim::SolverChoice choice,
                                             sim::GpuSolverFactory gpu, std::function<void(const std::string&)> notify) {
  sim::SessionSpec spec = session_spec(checkpoint.scene);
  spec.notify = std::move(notify);
  auto session = std::make_unique<sim::Session>(std::move(spec), choice, std::move(gpu));
  session->restore(checkpoint.image);
  return session;
}

}  // namespace pond::scene
