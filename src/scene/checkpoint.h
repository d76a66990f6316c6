#pragma once
// A checkpoint: one file holding all that continuing a simulation needs (docs/checkpoints.md): the
// scene with every edit made at run time (physics, sun, constraints, bodies added or removed), the
// water's state and the bodies', the step count, the wind's and the rain's state. A session made
// from its scene and given its image (sim::Session::restore) goes on with the bits of a run that
// never stopped, on any solver. The file is sealed (core/sealed_file.h): a truncated, corrupt or
// foreign one is refused with one line naming it.
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <vector>
#include <string>
#include <string_view>

#include "core/sealed_file.h"
#include "scene/scene.h"
#include "sim/session.h"

namespace pond::scene {

struct Checkpoint {
  Scene scene;
  sim::SessionImage image;
};

// Writes FILE atomically: `image` of a session whose scene is `scene` (its camera, view, lighting
// and tree as the front end has them; its water, sun and wind are taken from the session).
void write_checkpoint(const std::filesystem::path& path, const Scene& scene, const sim::Session& session,
                      const sim::SessionImage& image);
// The checkpoint in FILE; InputError naming the file and what is wrong.
Checkpoint read_checkpoint(const std::filesystem::path& path);
Checkpoint decode_checkpoint(std::string_view bytes, const std::string& name);  // a whole file's bytes

// The sealed file's format, and a payload sealed as a checkpoint file: how tests and the fuzz
// target reach the payload's reader past the checksum.
const SealedFormat& checkpoint_format();
std::vector<std::byte> seal_checkpoint(std::span<const std::byte> payload);

// A session continuing `checkpoint` on `choice`, with `gpu` for GPU solvers and `notify` as its
// spec's (sim/session.h).
std::unique_ptr<sim::Session> resume_session(const Checkpoint& checkpoint, sim::SolverChoice choice,
                                             sim::GpuSolverFactory gpu,
                                             std::function<void(const std::string&)> notify = {});

}  // namespace pond::scene
