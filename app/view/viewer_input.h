#pragma once
// What the mouse and the keys do, without a window: the GLFW callbacks
// (viewer_window.cpp) translate their events into these calls, and the
// tests make the same calls with synthetic events.
//   Shift + left drag   the scalpel (cuts along the drag)
//   left drag           orbit          right or middle drag   pan
//   scroll              zoom           R  reset the camera
//   Space  pause        N  one step    W  wireframe   L  LOD colours
//   F  flat/smooth shading      B  finest surface / the simulated frontier's

#include "app/view/orbit_camera.h"
#include "app/view/viewer_session.h"

namespace mtcut::app::view {

enum class MouseButton { kLeft, kRight, kMiddle };

enum class KeyAction {
  kResetCamera,
  kTogglePause,
  kStepOnce,
  kToggleWireframe,
  kToggleLodColors,
  kToggleShading,
  kToggleSurface
};

// The on-screen help (the panel shows it).
inline constexpr const char* kInputHelp =
    "Shift + left drag: scalpel (cuts)\n"
    "Left drag: orbit   Right/middle drag: pan\n"
    "Scroll: zoom   R: reset camera   Space: pause\n"
    "N: one step   W: wireframe   L: LOD colours   F: shading\n"
    "B: finest surface / simulated frontier";

class ViewerInput {
 public:
  ViewerInput(ViewerSession& session, OrbitCamera& camera) : session_(session), camera_(camera) {}

  // The framebuffer's size in the same units as cursor positions.
  void set_viewport(int width, int height);
  void on_mouse_button(MouseButton button, bool pressed, bool shift, double x, double y);
  void on_cursor(double x, double y);
  void on_scroll(double steps);
  void on_key(KeyAction action);

  bool scalpel_dragging() const { return drag_ == Drag::kScalpel; }

 private:
  enum class Drag { kNone, kOrbit, kPan, kScalpel };

  ViewerSession& session_;
  OrbitCamera& camera_;
  int width_ = 1, height_ = 1;
  Drag drag_ = Drag::kNone;
  double last_x_ = 0, last_y_ = 0;
};

}  // namespace mtcut::app::view
