#include "tests/app/view/tiny_mt.h"

#include <utility>

#include "engine/tet_geometry.h"

namespace mtcut::test {
namespace {

using engine::Vec3;
using engine::VertId;

// Appends tet (a, b, c, d), swapping two corners if it is negatively oriented.
void add_positive(engine::TetMesh& mesh, int a, int b, int c, int d) {
  engine::Tet t{VertId(a), VertId(b), VertId(c), VertId(d)};
  if (engine::signed_volume(mesh.position(t[0]), mesh.position(t[1]), mesh.position(t[2]), mesh.position(t[3])) < 0)
    std::swap(t[2], t[3]);
  mesh.tets.push_back(t);
}

}  // namespace

engine::TetMesh three_piece_mesh() {
  engine::TetMesh mesh;
  mesh.positions = {Vec3(0, 0, 0),  Vec3(1, 0, 0),  Vec3(0, 1, 0),  Vec3(0, 0, 1),   // A
                    Vec3(1, 1, 1),                                                   // B's apex
                    Vec3(5, 0, 0),  Vec3(6, 0, 0),  Vec3(5, 1, 0),  Vec3(5, 0, 1),   // C
                    Vec3(-1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0, -1), Vec3(0, 0, 0)};  // E with 0's copy
  add_positive(mesh, 0, 1, 2, 3);
  add_positive(mesh, 1, 2, 3, 4);
  add_positive(mesh, 5, 6, 7, 8);
  add_positive(mesh, 12, 9, 10, 11);
  return mesh;
}

TinyWorld make_tiny_world(const engine::TetMesh& mesh) {
  TinyWorld w{engine::Mt::from_fine_mesh(mesh), {}, {}};
  w.frontier = engine::Frontier::finest(w.mt);
  std::vector<engine::Tet> tets;
  for (engine::TetId t : w.frontier.tets()) tets.push_back(w.mt.tet(t));
  w.model = sim::build_spring_model(tets, w.mt.positions(), sim::MaterialDef{});
  return w;
}

}  // namespace mtcut::test
