// The demo's construction, its frame and its run loop (demo_app_impl.h); input is demo_input.cpp.
#include <chrono>
#include <cmath>
#include <cstdio>

#include "app/demo/bodies_panel.h"
#include "app/demo/demo_app_impl.h"
#include "app/demo/run_totals.h"
#include "app/demo/scene_modes.h"
#include "core/errors.h"
#include "core/output_file.h"
#include "core/output_paths.h"
#include "core/text.h"
#include "gpu/gpu_failure.h"
#include "render/render_target.h"
#include "scene/session_spec.h"
#include "sim/backends.h"

namespace pond::app::demo {
namespace {

static_assert(Swapchain::kAcquireRing == render::kFramesInFlight + 1,
              "the acquire-semaphore ring relies on the frame loop's slot fences (swapchain.h)");

using Clock = std::chrono::steady_clock;

double ms_between(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }

// X11 takes window coordinates as 16-bit signed numbers; larger sizes end in an X error.
constexpr int kMaxWindowSide = 32767;

// Every requested screenshot has a frame the run draws: --screenshot is the last of --frames N, a
// script's screenshot must come before it.
void check_requested_shots(const DemoOptions& options, const Script& script) {
  if (!options.screenshot.empty() && options.frames == 0)
    throw InputError("--screenshot saves the last frame of --frames N: give --frames");
  if (options.frames == 0) return;
  for (const ScriptEvent& e : script.events)
    if (e.event.kind == InputEvent::Kind::screenshot && e.frame >= options.frames)
      throw InputError("--script " + escaped(options.script) + " line " +
                       std::to_string(script.screenshot_lines[static_cast<std::size_t>(e.event.screenshot)]) +
                       ": screenshot at frame " + std::to_string(e.frame) + " is past the last frame (--frames " +
                       std::to_string(options.frames) + " ends after frame " + std::to_string(options.frames - 1) + ")");
}

// The window's size as the swapchain will get it, refused (InputError, as `pond render` refuses a
// --size) beyond what the device can draw; the script's resizes too.
vk::Extent2D checked_extent(const gpu::Context& ctx, const Window& window, const DemoOptions& options, const Script& script) {
  render::check_target_size(ctx, options.width, options.height, render::RenderTarget::kFormat);
  for (const ScriptEvent& e : script.events)
    if (e.event.kind == InputEvent::Kind::resize) {
      try {
        render::check_target_size(ctx, static_cast<int>(e.event.x), static_cast<int>(e.event.y), render::RenderTarget::kFormat);
      } catch (const InputError& bad) {
        throw InputError("--script resize at frame " + std::to_string(e.frame) + ": " + bad.what());
      }
    }
  return window.framebuffer_extent();
}

}  // namespace

std::string solver_label(const sim::SolverChoice& s) {
  return s.gpu ? "GPU solver" : std::string("CPU solver (") + sim::backend_name(s.backend) + ")";
}

DemoApp::DemoApp(const DemoOptions& options, scene::Scene scene, Script script)
    : options_(options),
      base_scene_(std::move(scene)),
      script_(std::move(script)),
      window_(options.width, options.height, "pond"),
      imgui_session_(window_.handle()),
      gpu_(make_gpu_stack(options, window_, options.vsync, [&](const gpu::Context& ctx) {
        return checked_extent(ctx, window_, options, script_);
      })) {
  adopt_scene_settings();
  settings_.vsync = options.vsync;
  stats_.device = gpu_->ctx.device_name();
  if (!gpu_->swapchain.can_copy_images() && (!options.screenshot.empty() || !script_.screenshots.empty()))
    throw RuntimeError("this window's swapchain images cannot be read back, so no screenshots can be taken");
  make_session(scene_with_settings(), nullptr);  // a GPU solver that fails here leaves the session on the CPU
  try {
    gpu::guard_gpu(gpu_->ctx, "while setting up the frame", [&] { build_loop(); });
  } catch (const GpuFailure& failure) {
    recover(failure);
  }
  const vk::Extent2D e = gpu_->swapchain.extent();
  camera_.set_home(loop_->default_camera(static_cast<int>(e.width), static_cast<int>(e.height)));
  // Half a spacing above the land, itself above the rest plane: the view stays out of the water.
  camera_.set_lowest_eye(base_scene_.basin.land_height + 0.5 * base_scene_.grid.spacing);
}

void DemoApp::adopt_scene_settings() {
  settings_.physics = base_scene_.physics;
  settings_.modes = modes_of(base_scene_);
  settings_.steps_per_frame = base_scene_.view.steps_per_frame;
  settings_.lod_tolerance_px = base_scene_.view.lod_tolerance_px;
  settings_.effects = base_scene_.view.effects;
  settings_.sun = base_scene_.lighting.sun;
}

DemoApp::~DemoApp() {
  if (gpu_) gpu_->ctx.wait_idle_for_teardown();  // frames in flight may use what goes first
}

void DemoApp::make_session(const scene::Scene& scene, const sim::SessionImage* image) {
  sim::SessionSpec spec = scene::session_spec(scene);
  spec.notify = [this](const std::string& text) { notice(text); };
  sim::SolverChoice choice;
  if (!settings_.gpu_solver) choice = sim::SolverChoice{.gpu = false, .backend = sim::best_backend()};
  session_.reset();
  session_ = std::make_unique<sim::Session>(std::move(spec), choice, gpu_->solvers.factory());
  if (image) session_->restore(*image);
  session_->track_tile_bounds(true);  // the LOD descends them instead of reading every node
  settings_.gpu_solver = session_->choice().gpu;
  stats_.solver = solver_label(session_->choice());
}

scene::Scene DemoApp::scene_with_settings() const {
  scene::Scene scene = apply_modes(base_scene_, settings_.modes);
  scene.physics = settings_.physics;
  scene.lighting.sun = settings_.sun;
  return scene;
}

// A loop for the session's current model (its land follows the constraints); the tree with the
// controls' changes carried over, and what the passes of the loop it replaces carry (the foam: the
// same water goes on).
void DemoApp::build_loop() {
  render::CarriedPasses carried;
  if (loop_) {
    loop_->wait_idle();
    carried = loop_->carry_passes();
  }
  loop_.reset();  // one loop at a time: its buffers and pipelines are the big allocations
  drawn_scene_ = scene_with_settings();
  loop_ = std::make_unique<render::FrameLoop>(gpu_->ctx, drawn_scene_, *session_, &gpu_->solvers, gpu_->swapchain.format());
  loop_->adopt_passes(std::move(carried));
  if (drawn_scene_.tree) {  // drawn before the UI
    const tree::TreeSpec spec = tree_ ? tree_->spec() : *drawn_scene_.tree;
    tree_.reset();
    tree_.emplace(gpu_->ctx, *loop_, spec);
    loop_->add_drawable(*tree_);
  }
  bodies_.reset();
  bodies_.emplace(gpu_->ctx, *loop_);
  loop_->add_drawable(*bodies_);
  loop_->add_drawable(gpu_->imgui);
}

void DemoApp::draw_ui() {
  ImGui_ImplGlfw_NewFrame();
  // Scripted runs and resizes: ImGui's display size follows the swapchain, not the window query.
  ImGuiIO& io = ImGui::GetIO();
  const vk::Extent2D extent = gpu_->swapchain.extent();
  io.DisplaySize = ImVec2(static_cast<float>(extent.width), static_cast<float>(extent.height));
  io.DisplayFramebufferScale = ImVec2(1, 1);
  ImGui::NewFrame();
  PanelRequests req;
  if (settings_.show_panel) req = draw_panel(settings_, stats_, tree_ ? &*tree_ : nullptr, *session_);
  BodyRequests bodies;
  if (settings_.show_panel) bodies = draw_bodies_panel(*session_, io.DisplaySize.x, settings_.ball_density);
  if (settings_.show_help) draw_help_overlay(settings_.show_help);
  ImGui::Render();
  apply_requests(req);
  if (bodies.remove) remove_body(*bodies.remove);
  if (bodies.add_ball) add_ball(middle_of_pond());
}

bool DemoApp::draw_frame(const std::vector<std::string>& shots) {
  Swapchain& swapchain = gpu_->swapchain;
  // The frame's wait for the last compute, its early passes and LOD first, then the swapchain
  // image: acquiring waits for the window system to have taken the last frame, which this way
  // overlaps with them. A frame prepared before a failed acquire is drawn after the swapchain's
  // recreation.
  if (!loop_->prepared())
    loop_->prepare(render::FrameView{.camera = current_camera(), .lod_tolerance_px = settings_.lod_tolerance_px,
                                     .wireframe = settings_.wireframe, .effects = settings_.effects},
                   swapchain.extent());
  const Clock::time_point t0 = Clock::now();
  const std::optional<AcquiredImage> image = swapchain.acquire();
  acquire_ms_ = ms_between(t0, Clock::now());
  if (!image) return false;
  const vk::Extent2D extent = swapchain.extent();
  const bool shot = !shots.empty();
  const render::FrameTarget target{.image = image->image, .view = image->view, .format = swapchain.format(),
                                   .extent = extent, .old_layout = vk::ImageLayout::eUndefined,
                                   .final_layout = shot ? vk::ImageLayout::eTransferSrcOptimal : vk::ImageLayout::ePresentSrcKHR,
                                   .wait_semaphore = image->acquired,
                                   .signal_semaphore = shot ? gpu_->shots.drawn() : image->rendered};
  stats_.last = loop_->draw(target);
  stats_.steps_done = session_->steps_done();
  if (shot) {
    gpu_->shots.save(image->image, swapchain.format(), extent, image->rendered, shots);
    settings_.message = "saved";
    for (const std::string& path : shots) settings_.message += " " + escaped(path), written_.insert(path);
  }
  const Clock::time_point t1 = Clock::now();
  const bool current = swapchain.present(*image);
  present_ms_ = ms_between(t1, Clock::now());
  if (!current) swapchain.recreate(window_.framebuffer_extent(), settings_.vsync);
  return true;
}

// After presenting: the GPU's compute is submitted and overlaps the window system's copy; the next
// frame waits for it once.
void DemoApp::step() {
  std::int64_t steps = settings_.paused ? 0 : settings_.steps_per_frame;
  if (settings_.step_once) steps = std::max<std::int64_t>(steps, 1), settings_.step_once = false;
  grab_.drag(*session_, current_camera(), steps);  // a held body toward the cursor over these steps
  const Clock::time_point t = Clock::now();
  session_->advance(steps);
  stats_.simulate_ms = ms_between(t, Clock::now());
}

// This frame's script events join the window's, in the same dispatch.
void DemoApp::handle_script_events(std::int64_t frame, std::size_t& next_event) {
  std::vector<InputEvent>& events = window_.events();
  for (; next_event < script_.events.size() && script_.events[next_event].frame <= frame; ++next_event) {
    const InputEvent& e = script_.events[next_event].event;
    if (e.kind == InputEvent::Kind::resize) {
      window_.set_size(static_cast<int>(e.x), static_cast<int>(e.y));
    } else if (e.kind == InputEvent::Kind::minimize) {
      window_.minimize();
    } else if (e.kind == InputEvent::Kind::restore) {
      window_.restore();
    } else if (e.kind == InputEvent::Kind::screenshot) {
      take_screenshot_next(script_.screenshots[static_cast<std::size_t>(e.screenshot)]);
    } else if (e.kind == InputEvent::Kind::remove_body) {
      remove_body(static_cast<std::size_t>(e.code));
    } else if (e.kind == InputEvent::Kind::add_ball) {
      add_ball(middle_of_pond());
    } else if (e.kind == InputEvent::Kind::save) {
      save_checkpoint(script_.checkpoints[static_cast<std::size_t>(e.screenshot)]);
    } else if (e.kind == InputEvent::Kind::load) {
      load_checkpoint(script_.checkpoints[static_cast<std::size_t>(e.screenshot)]);
    } else {
      events.push_back(e);
    }
  }
}

int DemoApp::run() {
  const Clock::time_point start = Clock::now();
  Clock::time_point last = start;
  std::size_t next_event = 0;
  std::int64_t frame = 0, minimized_frames = 0;
  RunTotals totals;
  while (!quit_ && (options_.frames == 0 || frame < options_.frames)) {
    frame_ = frame;
    window_.poll();
    if (window_.should_close()) break;
    // Everything of a frame that may touch the device (a key's action too) fails as one: the demo
    // makes its device again and runs the frame anew; the events already handled stay handled.
    bool drawn = false;
    try {
      drawn = gpu::guard_gpu(gpu_->ctx, "during a frame", [&] {
        handle_script_events(frame, next_event);
        std::vector<InputEvent>& events = window_.events();
        const ImGuiIO& io = ImGui::GetIO();
        const double now = glfwGetTime();
        for (const InputEvent& e : events) input_.dispatch(e, io.WantCaptureMouse, io.WantCaptureKeyboard, now, *this);
        events.clear();
        return quit_ || frame_on_device(frame, minimized_frames, totals, last);
      });
    } catch (const GpuFailure& failure) {
      window_.events().clear();
      recover(failure);
      continue;
    }
    if (quit_) break;
    if (!drawn) continue;  // the swapchain was out of date: the same frame again
    recoveries_ = 0;
    ++frame;
  }
  gpu_->ctx.wait_idle_for_teardown();  // every frame and compute done: nothing left for the rings to wait for
  if (minimized_frames > 0 && !options_.quiet)
    std::printf("pond demo: %lld of %lld frames minimized (nothing drawn)\n", static_cast<long long>(minimized_frames),
                static_cast<long long>(frame));
  if (!options_.screenshot.empty() && window_.minimized() && options_.frames > 0)
    throw RuntimeError("the window was minimized at the last frame: no screenshot for " + quote(options_.screenshot));
  check_screenshots_written(frame);
  if (!options_.quiet)
    totals.print(gpu_->swapchain.extent().width, gpu_->swapchain.extent().height, gpu_->ctx.device_name(), stats_.solver,
                 stats_.present_mode, stats_.last.full_triangles);
  const std::size_t messages = earlier_validation_messages_ + gpu_->ctx.validation_log().count();
  if (options_.validation && messages > 0)
    throw RuntimeError(std::to_string(messages) + " Vulkan validation message(s) were logged (see above)");
  return 0;
}

bool DemoApp::frame_on_device(std::int64_t frame, std::int64_t& minimized_frames, RunTotals& totals,
                              Clock::time_point& last) {
  // Minimized: draw nothing and sleep until something happens (at most 0.1 s). The frame still
  // counts, so --frames ends and a script's later events (a restore) still come.
  if (window_.minimized()) {
    window_.wait(0.1);
    ++minimized_frames;
    return true;
  }
  Swapchain& swapchain = gpu_->swapchain;
  const vk::Extent2D fb = window_.framebuffer_extent();
  if (fb != swapchain.extent() || settings_.vsync != swapchain.vsync()) swapchain.recreate(fb, settings_.vsync);
  stats_.width = static_cast<int>(swapchain.extent().width);
  stats_.height = static_cast<int>(swapchain.extent().height);
  stats_.present_mode = vk::to_string(swapchain.present_mode());

  if (settings_.rain.on) {
    const double h = session_->model().spacing;
    session_->rain(settings_.rain.drops_per_frame, settings_.rain.radius * h, settings_.rain.amplitude * h);
  }
  // The trees' wind in real time (the water runs faster): the previous frame's wall time.
  session_->advance_wind(stats_.frame_ms / 1000.0);
  draw_ui();
  const bool last_frame = options_.frames > 0 && frame + 1 == options_.frames;
  std::vector<std::string> shots = pending_shots_;  // kept for a retry of this frame
  if (last_frame && !options_.screenshot.empty()) shots.push_back(options_.screenshot);
  if (!draw_frame(shots)) {
    swapchain.recreate(window_.framebuffer_extent(), settings_.vsync);
    return false;
  }
  pending_shots_.clear();
  step();
  const Clock::time_point t = Clock::now();
  const double ms = ms_between(last, t);
  last = t;
  stats_.frame_ms = totals.drawn == 0 ? ms : 0.9 * stats_.frame_ms + 0.1 * ms;
  stats_.fps = stats_.frame_ms > 0 ? 1000.0 / stats_.frame_ms : 0;
  totals.add(ms, stats_.last, stats_.simulate_ms, acquire_ms_, present_ms_);
  return true;
}

void DemoApp::check_screenshots_written(std::int64_t frames_run) const {
  const std::string ended = "the demo ended after " + std::to_string(frames_run) + " frame" + (frames_run == 1 ? "" : "s");
  for (const ScriptEvent& e : script_.events)
    if (e.event.kind == InputEvent::Kind::screenshot) {
      const auto k = static_cast<std::size_t>(e.event.screenshot);
      if (!written_.contains(script_.screenshots[k]))
        throw RuntimeError("no screenshot " + quote(script_.screenshots[k]) + " (--script line " +
                           std::to_string(script_.screenshot_lines[k]) + ", frame " + std::to_string(e.frame) + "): " + ended);
    }
  if (!options_.screenshot.empty() && !written_.contains(options_.screenshot))
    throw RuntimeError("no screenshot " + quote(options_.screenshot) + " (--screenshot, frame " +
                       std::to_string(options_.frames - 1) + "): " + ended);
}

int run_demo(const DemoOptions& options) {
  // Bad input first, before any window: exit 2 even on a machine without a display.
  scene::Scene scene = scene::load_scene(options.scene);
  Script script = load_script(options.script);
  check_requested_shots(options, script);
  if (options.width > kMaxWindowSide || options.height > kMaxWindowSide)
    throw InputError("--size " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                     ": a window takes at most " + std::to_string(kMaxWindowSide) + " pixels a side (X11's coordinates)");
  if (!options.screenshot.empty()) check_output_path(options.screenshot);
  NamedPaths shots{{"--screenshot", options.screenshot}};
  for (std::size_t k = 0; k < script.screenshots.size(); ++k)
    shots.emplace_back("--script line " + std::to_string(script.screenshot_lines[k]) + ": screenshot", script.screenshots[k]);
  check_distinct_outputs(shots);  // one would overwrite the other
  check_outputs_spare_inputs(shots, {{"--scene", options.scene}, {"--script", options.script}});
  DemoApp app(options, std::move(scene), std::move(script));
  return app.run();
}

}  // namespace pond::app::demo
