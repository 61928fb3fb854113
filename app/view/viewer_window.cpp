#include "app/view/viewer_window.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <epoxy/gl.h>
#include <iostream>
#include <string>

// GLFW after epoxy: epoxy provides the GL declarations.
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "app/view/scene_renderer.h"
#include "engine/input_error.h"
#include "engine/stopwatch.h"

namespace mtcut::app::view {
namespace {

using Clock = std::chrono::steady_clock;

std::string& last_glfw_error() {
  static std::string error;
  return error;
}

void record_glfw_error(int /*code*/, const char* description) { last_glfw_error() = description; }

ViewerWindow& owner(GLFWwindow* window) { return *static_cast<ViewerWindow*>(glfwGetWindowUserPointer(window)); }

GLFWwindow* open_window(int width, int height) {
  glfwSetErrorCallback(record_glfw_error);
  require_display();
  if (!glfwInit()) throw engine::InputError("view: cannot open a window (" + last_glfw_error() + ")");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SAMPLES, 4);
  GLFWwindow* window = glfwCreateWindow(width, height, "mtcut view", nullptr, nullptr);
  if (!window) {
    const std::string why = last_glfw_error();
    glfwTerminate();
    throw engine::InputError("view: cannot open a window with OpenGL 3.3 core (" + why + ")");
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  return window;
}

}  // namespace

void require_display() {
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!display || !*display) && (!wayland || !*wayland))
    throw engine::InputError("view: cannot open a window (no DISPLAY); run under xvfb-run");
}

ViewerWindow::ViewerWindow(ViewerSession& session, const WindowOptions& options)
    : session_(session),
      options_(options),
      window_(open_window(options.width, options.height)),
      input_(session, camera_),
      panel_(session.world().def()),
      clock_(session.world().def().dt) {
  camera_.frame(session.lo(), session.hi());
  glfwSetWindowUserPointer(window_, this);
  // Ours first: ImGui's back end chains to them, and they ask ImGui whether it wants the event.
  glfwSetMouseButtonCallback(window_, on_mouse_button);
  glfwSetCursorPosCallback(window_, on_cursor);
  glfwSetScrollCallback(window_, on_scroll);
  glfwSetKeyCallback(window_, on_key);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the user's folder
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  glEnable(GL_MULTISAMPLE);
  renderer_ = std::make_unique<SceneRenderer>();
}

ViewerWindow::~ViewerWindow() {
  renderer_.reset();
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void ViewerWindow::on_mouse_button(GLFWwindow* window, int button, int action, int mods) {
  ViewerWindow& self = owner(window);
  const bool pressed = action == GLFW_PRESS;
  // Presses on the panel are the panel's; releases always end a drag.
  if (pressed && ImGui::GetIO().WantCaptureMouse) return;
  double x = 0, y = 0;
  glfwGetCursorPos(window, &x, &y);
  const MouseButton which = button == GLFW_MOUSE_BUTTON_LEFT    ? MouseButton::kLeft
                            : button == GLFW_MOUSE_BUTTON_RIGHT ? MouseButton::kRight
                                                                : MouseButton::kMiddle;
  self.input_.on_mouse_button(which, pressed, (mods & GLFW_MOD_SHIFT) != 0, x, y);
}

void ViewerWindow::on_cursor(GLFWwindow* window, double x, double y) { owner(window).input_.on_cursor(x, y); }

void ViewerWindow::on_scroll(GLFWwindow* window, double /*dx*/, double dy) {
  if (!ImGui::GetIO().WantCaptureMouse) owner(window).input_.on_scroll(dy);
}

void ViewerWindow::on_key(GLFWwindow* window, int key, int /*scancode*/, int action, int /*mods*/) {
  if (action != GLFW_PRESS || ImGui::GetIO().WantCaptureKeyboard) return;
  ViewerInput& input = owner(window).input_;
  switch (key) {
    case GLFW_KEY_R: input.on_key(KeyAction::kResetCamera); break;
    case GLFW_KEY_SPACE: input.on_key(KeyAction::kTogglePause); break;
    case GLFW_KEY_N: input.on_key(KeyAction::kStepOnce); break;
    case GLFW_KEY_W: input.on_key(KeyAction::kToggleWireframe); break;
    case GLFW_KEY_L: input.on_key(KeyAction::kToggleLodColors); break;
    case GLFW_KEY_F: input.on_key(KeyAction::kToggleShading); break;
    case GLFW_KEY_B: input.on_key(KeyAction::kToggleSurface); break;
    case GLFW_KEY_ESCAPE: glfwSetWindowShouldClose(window, GLFW_TRUE); break;
    default: break;
  }
}

double ViewerWindow::draw_frame(Image* capture) {
  const auto start = Clock::now();
  if (last_draw_ != Clock::time_point{}) {
    // Smoothed over about ten frames.
    const double fps = 1.0 / std::max(std::chrono::duration<double>(start - last_draw_).count(), 1e-6);
    status_.display_fps = status_.display_fps > 0 ? 0.9 * status_.display_fps + 0.1 * fps : fps;
  }
  last_draw_ = start;
  int window_w = 0, window_h = 0, fb_w = 0, fb_h = 0;
  glfwGetWindowSize(window_, &window_w, &window_h);
  glfwGetFramebufferSize(window_, &fb_w, &fb_h);
  input_.set_viewport(window_w, window_h);
  renderer_->draw(session_, camera_, fb_w, fb_h);
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  if (options_.show_panel) requests_ = panel_.draw(session_, status_);
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  if (capture) *capture = SceneRenderer::read_pixels(fb_w, fb_h);
  glfwSwapBuffers(window_);
  const double ms = 1000.0 * engine::seconds_since(start);
  status_.render_ms = ms;
  session_.timings().render.push(ms);
  return ms;
}

void ViewerWindow::save_screenshot(const Image& image) {
  const std::string path = "mtcut-view-" + std::to_string(++screenshots_) + ".png";
  write_png(path, image);
  std::cerr << "mtcut view: wrote " << path << "\n";
}

void ViewerWindow::run() {
  auto last = Clock::now();
  auto speed_window_start = Clock::now();
  double speed_window_sim_start = session_.world().time();
  // Physics may take this much wall time per displayed frame; the rest of
  // its debt is dropped so the window stays responsive.
  constexpr double kPhysicsBudget = 1.0 / 20.0;
  while (!glfwWindowShouldClose(window_)) {
    glfwPollEvents();
    session_.poll_hid();
    const auto now = Clock::now();
    const double elapsed = std::chrono::duration<double>(now - last).count();
    last = now;
    if (!session_.settings().paused) {
      const int due = clock_.advance(elapsed);
      const auto physics_start = Clock::now();
      for (int i = 0; i < due; ++i) {
        if (i > 0 && engine::seconds_since(physics_start) > kPhysicsBudget) {
          clock_.drop(due - i);
          break;
        }
        session_.step();
      }
    }
    // The panel asked for a screenshot last frame: capture this one.
    const bool capture = requests_.screenshot;
    Image shot;
    draw_frame(capture ? &shot : nullptr);
    if (capture) save_screenshot(shot);
    if (requests_.clear_clock) clock_.clear();
    clock_.set_dt(session_.world().def().dt);

    const double window_seconds = engine::seconds_since(speed_window_start);
    if (window_seconds >= 1.0) {
      status_.sim_speed = std::max(session_.world().time() - speed_window_sim_start, 0.0) / window_seconds;
      speed_window_start = Clock::now();
      speed_window_sim_start = session_.world().time();
    }
    status_.dropped_steps = clock_.dropped_steps();
  }
}

}  // namespace mtcut::app::view
