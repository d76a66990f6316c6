#pragma once
// Physical diagnostics of a state, in world units and double precision: kinetic energy
// sum(m |v|^2 / 2), spring energy sum(c (l - L)^2 / 2) over every spring, and the largest
// displacement of a node from its rest position. And a 64-bit hash of the dumped state, the
// "golden hash" every backend must reproduce.
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "sim/model.h"
#include "sim/state.h"

namespace pond::sim {

struct Diagnostics {
  double kinetic = 0;
  double spring = 0;
  double max_displacement = 0;
  double total() const { return kinetic + spring; }
};

Diagnostics diagnose(const WaterState& state, const WaterModel& model);

// FNV-1a 64 over the bytes of the world-unit dump (to_world_interleaved).
std::uint64_t state_hash(std::span<const float> world_interleaved);
std::uint64_t state_hash(const WaterState& state, const WaterModel& model);

// The blow-up check: the first node whose velocity is not finite (or beyond 1e30), if any.
std::optional<std::size_t> first_blown_up_node(const WaterState& state);
// The first body whose position or velocity is not finite (or beyond 1e30), if any.
std::optional<std::size_t> first_blown_up_body(const WaterState& state);
// Throws InputError: "<prefix>the water blew up (non-finite velocity at node row R, col C); ..."
// naming the first such node (the last node when none is: the caller saw a non-finite sum), or
// "<prefix>body B blew up ..." when the nodes are finite and a body is not.
[[noreturn]] void throw_blow_up(const WaterState& state, const WaterModel& model, const std::string& prefix);

}  // namespace pond::sim
