#include "app/view/viewer_input.h"

#include "app/view/ray_pick.h"

namespace mtcut::app::view {

void ViewerInput::set_viewport(int width, int height) {
  width_ = width > 0 ? width : 1;
  height_ = height > 0 ? height : 1;
}

void ViewerInput::on_mouse_button(MouseButton button, bool pressed, bool shift, double x, double y) {
  last_x_ = x;
  last_y_ = y;
  if (!pressed) {
    if (drag_ == Drag::kScalpel) session_.mouse_scalpel().release();
    drag_ = Drag::kNone;
    return;
  }
  if (drag_ != Drag::kNone) return;  // a second button during a drag changes nothing
  if (button == MouseButton::kLeft && shift) {
    const Ray ray = camera_.ray_through(x, y, width_, height_);
    // A press off the organ starts nothing: the scalpel needs a surface point.
    if (session_.mouse_scalpel().press(ray, pick_surface(ray, session_.geometry().corner_position)))
      drag_ = Drag::kScalpel;
    return;
  }
  drag_ = button == MouseButton::kLeft ? Drag::kOrbit : Drag::kPan;
}

void ViewerInput::on_cursor(double x, double y) {
  const double dx = x - last_x_, dy = y - last_y_;
  last_x_ = x;
  last_y_ = y;
  switch (drag_) {
    case Drag::kOrbit: camera_.orbit(dx, dy); break;
    case Drag::kPan: camera_.pan(dx, dy, height_); break;
    case Drag::kScalpel: session_.mouse_scalpel().drag(camera_.ray_through(x, y, width_, height_)); break;
    case Drag::kNone: break;
  }
}

void ViewerInput::on_scroll(double steps) { camera_.zoom(steps); }

void ViewerInput::on_key(KeyAction action) {
  ViewSettings& s = session_.settings();
  switch (action) {
    case KeyAction::kResetCamera: camera_.reset(); break;
    case KeyAction::kTogglePause: s.paused = !s.paused; break;
    case KeyAction::kStepOnce:
      s.paused = true;
      session_.step();
      break;
    case KeyAction::kToggleWireframe: s.wireframe = !s.wireframe; break;
    case KeyAction::kToggleLodColors:
      s.color_mode = s.color_mode == ColorMode::kPieces ? ColorMode::kLodLevels : ColorMode::kPieces;
      break;
    case KeyAction::kToggleShading:
      s.shading = s.shading == Shading::kSmooth ? Shading::kFlat : Shading::kSmooth;
      session_.refresh_surface();
      break;
    case KeyAction::kToggleSurface:
      s.surface = s.surface == SurfaceKind::kFinest ? SurfaceKind::kFrontier : SurfaceKind::kFinest;
      session_.refresh_surface();
      break;
  }
}

}  // namespace mtcut::app::view
