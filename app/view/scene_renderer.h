#pragma once
// Draws a ViewerSession with OpenGL 3.3 core: the tissue's surface (lit,
// coloured by piece/cut or by LOD level, optional wireframe), the floor and
// the blade. Positions and normals are uploaded every frame; colours and
// buffer sizes only when the topology or the colour mode changed.

#include <cstdint>
#include <epoxy/gl.h>
#include <memory>
#include <vector>

#include "app/view/gl_program.h"
#include "app/view/orbit_camera.h"
#include "app/view/png_file.h"
#include "app/view/scene_props.h"
#include "app/view/viewer_session.h"

namespace mtcut::app::view {

class SceneRenderer {
 public:
  // Needs a current OpenGL 3.3 core context.
  SceneRenderer();
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  // Clears and draws into the current framebuffer (width x height pixels).
  void draw(const ViewerSession& session, const OrbitCamera& camera, int width, int height);

  // The current framebuffer's colour (call before swapping buffers).
  static Image read_pixels(int width, int height);

 private:
  void upload_surface(const ViewerSession& session);
  void draw_props(const std::vector<PropVertex>& vertices, bool lit);

  std::unique_ptr<GlProgram> program_;
  GLuint surface_vao_ = 0;
  GLuint surface_buffers_[3] = {0, 0, 0};  // positions, normals, colours (3 n_faces each)
  GLuint props_vao_ = 0, props_buffer_ = 0;
  std::size_t surface_capacity_ = 0;       // corners the buffers hold
  std::size_t surface_corners_ = 0;        // corners drawn
  std::uint64_t uploaded_topology_ = UINT64_MAX;
  ColorMode uploaded_mode_ = ColorMode::kPieces;
};

}  // namespace mtcut::app::view
