#pragma once
// The viewer's window: GLFW, an OpenGL 3.3 core context (libepoxy), Dear
// ImGui, the scene renderer, and the loop that keeps physics at its fixed
// dt while the display runs at its own rate (step_clock.h). GLFW's
// callbacks only translate events into ViewerInput calls.

#include <chrono>
#include <memory>
#include <string>

#include "app/view/orbit_camera.h"
#include "app/view/png_file.h"
#include "app/view/step_clock.h"
#include "app/view/viewer_input.h"
#include "app/view/viewer_panel.h"
#include "app/view/viewer_session.h"

struct GLFWwindow;

namespace mtcut::app::view {

class SceneRenderer;

// Throws InputError "view: cannot open a window (no DISPLAY); run under
// xvfb-run" when neither DISPLAY nor WAYLAND_DISPLAY is set (checked before
// the organ is built, so the user does not wait for it).
void require_display();

struct WindowOptions {
  int width = 1280, height = 720;  // pixels
  bool show_panel = true;
};

class ViewerWindow {
 public:
  // Opens the window and its context. Throws InputError "view: cannot open a
  // window (...)" when there is no display or no OpenGL 3.3.
  ViewerWindow(ViewerSession& session, const WindowOptions& options);
  ~ViewerWindow();
  ViewerWindow(const ViewerWindow&) = delete;
  ViewerWindow& operator=(const ViewerWindow&) = delete;

  // The interactive loop, until the window is closed.
  void run();
  // Draws one frame (scene and panel) without stepping; with `capture`,
  // returns what it drew (else an empty Image). Returns the drawing time.
  double draw_frame(Image* capture = nullptr);

  ViewerInput& input() { return input_; }
  OrbitCamera& camera() { return camera_; }

 private:
  static void on_mouse_button(GLFWwindow* window, int button, int action, int mods);
  static void on_cursor(GLFWwindow* window, double x, double y);
  static void on_scroll(GLFWwindow* window, double dx, double dy);
  static void on_key(GLFWwindow* window, int key, int scancode, int action, int mods);
  void save_screenshot(const Image& image);

  ViewerSession& session_;
  WindowOptions options_;
  GLFWwindow* window_ = nullptr;
  OrbitCamera camera_;
  ViewerInput input_;
  ViewerPanel panel_;
  StepClock clock_;
  std::unique_ptr<SceneRenderer> renderer_;
  PanelStatus status_;
  PanelRequests requests_;
  int screenshots_ = 0;
  std::chrono::steady_clock::time_point last_draw_{};  // for the display rate
};

}  // namespace mtcut::app::view
