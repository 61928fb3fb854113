#include "app/view/scene_renderer.h"

#include <glm/gtc/type_ptr.hpp>

#include "app/view/surface_colors.h"

namespace mtcut::app::view {
namespace {

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_color;
uniform mat4 u_view_projection;
out vec3 v_position;
out vec3 v_normal;
out vec3 v_color;
void main() {
  v_position = a_position;
  v_normal = a_normal;
  v_color = a_color;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
)";

// Diffuse only (a key light and a headlight), no specular: shading scales a
// colour without changing its hue, which the screenshot tests rely on.
constexpr const char* kFragmentShader = R"(#version 330 core
in vec3 v_position;
in vec3 v_normal;
in vec3 v_color;
uniform vec3 u_eye;
uniform vec3 u_light;
uniform int u_lit;
uniform int u_flat_color;
uniform vec3 u_color;
out vec4 o_color;
void main() {
  if (u_flat_color == 1) { o_color = vec4(u_color, 1.0); return; }
  if (u_lit == 0) { o_color = vec4(v_color, 1.0); return; }
  vec3 to_eye = normalize(u_eye - v_position);
  vec3 n = length(v_normal) > 1e-6 ? normalize(v_normal) : to_eye;
  if (!gl_FrontFacing) n = -n;
  float shade = 0.30 + 0.45 * max(dot(n, u_light), 0.0) + 0.30 * max(dot(n, to_eye), 0.0);
  o_color = vec4(v_color * min(shade, 1.0), 1.0);
}
)";

void attribute(GLuint index, GLuint buffer, GLsizei stride, std::size_t offset) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glEnableVertexAttribArray(index);
  glVertexAttribPointer(index, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offset));
}

}  // namespace

SceneRenderer::SceneRenderer() : program_(std::make_unique<GlProgram>(kVertexShader, kFragmentShader)) {
  glGenVertexArrays(1, &surface_vao_);
  glGenBuffers(3, surface_buffers_);
  glBindVertexArray(surface_vao_);
  for (GLuint i = 0; i < 3; ++i) attribute(i, surface_buffers_[i], 0, 0);

  glGenVertexArrays(1, &props_vao_);
  glGenBuffers(1, &props_buffer_);
  glBindVertexArray(props_vao_);
  attribute(0, props_buffer_, sizeof(PropVertex), offsetof(PropVertex, position));
  attribute(1, props_buffer_, sizeof(PropVertex), offsetof(PropVertex, normal));
  attribute(2, props_buffer_, sizeof(PropVertex), offsetof(PropVertex, color));
  glBindVertexArray(0);
}

SceneRenderer::~SceneRenderer() {
  glDeleteBuffers(3, surface_buffers_);
  glDeleteBuffers(1, &props_buffer_);
  glDeleteVertexArrays(1, &surface_vao_);
  glDeleteVertexArrays(1, &props_vao_);
}

void SceneRenderer::upload_surface(const ViewerSession& session) {
  const SurfaceGeometry& g = session.geometry();
  const std::size_t corners = g.corner_position.size();
  const GLsizeiptr bytes = static_cast<GLsizeiptr>(corners * sizeof(glm::vec3));
  const ColorMode mode = session.settings().color_mode;
  const bool topology_changed = session.topology_version() != uploaded_topology_ || mode != uploaded_mode_;
  if (corners > surface_capacity_) {
    // Grow with headroom: a cut or a refinement adds faces a few at a time.
    surface_capacity_ = corners + corners / 4;
    for (GLuint buffer : surface_buffers_) {
      glBindBuffer(GL_ARRAY_BUFFER, buffer);
      glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(surface_capacity_ * sizeof(glm::vec3)), nullptr,
                   GL_DYNAMIC_DRAW);
    }
  }
  glBindBuffer(GL_ARRAY_BUFFER, surface_buffers_[0]);
  glBufferSubData(GL_ARRAY_BUFFER, 0, bytes, g.corner_position.data());
  glBindBuffer(GL_ARRAY_BUFFER, surface_buffers_[1]);
  glBufferSubData(GL_ARRAY_BUFFER, 0, bytes, g.corner_normal.data());
  if (topology_changed || corners != surface_corners_) {
    const std::vector<glm::vec3> colors = corner_colors(session.topology(), mode);
    glBindBuffer(GL_ARRAY_BUFFER, surface_buffers_[2]);
    glBufferSubData(GL_ARRAY_BUFFER, 0, bytes, colors.data());
    uploaded_topology_ = session.topology_version();
    uploaded_mode_ = mode;
  }
  surface_corners_ = corners;
}

void SceneRenderer::draw_props(const std::vector<PropVertex>& vertices, bool lit) {
  if (vertices.empty()) return;
  glUniform1i(program_->uniform("u_lit"), lit ? 1 : 0);
  glBindVertexArray(props_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, props_buffer_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(PropVertex)), vertices.data(),
               GL_STREAM_DRAW);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
}

void SceneRenderer::draw(const ViewerSession& session, const OrbitCamera& camera, int width, int height) {
  glViewport(0, 0, width, height);
  glClearColor(kBackgroundColor.r, kBackgroundColor.g, kBackgroundColor.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);

  const glm::mat4 view_projection(camera.projection(static_cast<double>(width) / std::max(height, 1)) * camera.view());
  const glm::vec3 eye(camera.eye());
  // The key light comes from above, over the camera's right shoulder.
  const glm::vec3 light = glm::normalize(glm::vec3(0, 0, 1) + 0.5f * glm::normalize(eye - glm::vec3(camera.target())));
  glUseProgram(program_->id());
  glUniformMatrix4fv(program_->uniform("u_view_projection"), 1, GL_FALSE, glm::value_ptr(view_projection));
  glUniform3fv(program_->uniform("u_eye"), 1, glm::value_ptr(eye));
  glUniform3fv(program_->uniform("u_light"), 1, glm::value_ptr(light));
  glUniform1i(program_->uniform("u_flat_color"), 0);

  const ViewSettings& s = session.settings();
  const auto& env = session.world().def().environment;
  if (s.show_floor && env.floor) {
    // Tissue resting on the floor lies in its plane: push the floor back so
    // the tissue (and its wireframe) wins the depth test there.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(4.0f, 16.0f);
    draw_props(floor_triangles(*env.floor, session.lo(), session.hi()), true);
    glDisable(GL_POLYGON_OFFSET_FILL);
  }

  upload_surface(session);
  glBindVertexArray(surface_vao_);
  glUniform1i(program_->uniform("u_lit"), 1);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);  // the wireframe drawn next stays in front of its own faces
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(surface_corners_));
  glDisable(GL_POLYGON_OFFSET_FILL);
  if (s.wireframe) {
    glUniform1i(program_->uniform("u_flat_color"), 1);
    glUniform3f(program_->uniform("u_color"), 0.08f, 0.08f, 0.08f);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(surface_corners_));
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glUniform1i(program_->uniform("u_flat_color"), 0);
  }

  if (s.show_blade) {
    // Over everything: the blade is mostly inside the tissue while it cuts.
    glDisable(GL_DEPTH_TEST);
    draw_props(blade_triangles(session.last_pose(), camera.eye(), 0.015 * camera.radius()), false);
    glEnable(GL_DEPTH_TEST);
  }
  glBindVertexArray(0);
  glUseProgram(0);
}

Image SceneRenderer::read_pixels(int width, int height) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  return image_from_bottom_up(width, height, rgba);
}

}  // namespace mtcut::app::view
