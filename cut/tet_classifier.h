#pragma once
// Classification of tetrahedra against one cut polygon: which side of the
// plane each vertex is on, which edges the polygon crosses, and where new
// points go. Exact where a decision is made (orient3d), floating point where
// a point is only placed.
//
// Why two phases. Whether a cut point near a vertex snaps onto that vertex
// must be the same for every tet around the vertex, otherwise neighbours
// would disagree on the vertex's side and the mesh would tear. So the cutter
// first shows the classifier every tet that may be cut (add_candidate: raw
// exact sides, crossing parameters, snap marks), then finalize() fixes one
// state per vertex. After that each tet's configuration is a pure function of
// its four vertices, and so is its split (tet_splitter.h).
//
// Vertex states after finalize():
//   kNeg / kPos    strictly on one side (exact orient3d);
//   kOnActive      on the cut and inside the polygon (or within the snap
//                  margin of it): the cut passes through the vertex, which is
//                  split in two (the positive side keeps the id);
//   kOnInactive    on the plane but outside the polygon: the cut may end at
//                  it (a contour point), it is never split.
// A vertex is "on" when it is exactly on the plane, or when a straddling edge
// of a candidate tet meets the plane within `snap` (a fraction of the edge)
// of it. The vertex is not moved: the cut surface bends through it. Hence
// every cut point left on an edge lies in [snap, 1 - snap] of it, and no
// sliver is made (DESIGN.md, "Degenerate contacts").

#include <array>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "cut/cut_polygon.h"
#include "engine/tet_mesh.h"

namespace mtcut::cut {

using engine::Tet;
using engine::VertId;

enum class VertexState : std::uint8_t { kNeg = 0, kPos = 1, kOnActive = 2, kOnInactive = 3 };

inline bool is_strict(VertexState s) { return s == VertexState::kNeg || s == VertexState::kPos; }
inline bool is_on(VertexState s) { return !is_strict(s); }

// The cases of DESIGN.md's LUT, plus O (two opposite edges) and the
// degenerate ones where the cut passes through a vertex or along an edge.
enum class CutCase : std::uint8_t { kA, kB, kC, kD, kE, kO, kVertex, kCount };
const char* case_name(CutCase c);

// What a single tet sees of a cut: the key of its split.
struct TetConfig {
  std::array<VertexState, 4> vertex{};
  std::uint8_t covered = 0;     // bit k: local edge k (kTetEdges) straddles and crosses inside the polygon
  std::array<std::uint8_t, 4> rank{0, 1, 2, 3};  // rank of each local vertex's global id (0 = lowest)

  bool straddles(int edge) const;
  bool edge_active(int edge) const { return straddles(edge) && (covered >> edge & 1); }
  // Split needed: an edge crossed inside the polygon, or the cut passing
  // through a vertex into a tet that has vertices on both sides.
  bool is_cut() const;
  // 8 bits of states, 6 of coverage (straddling edges only), 5 of id order.
  std::uint32_t key() const;
  CutCase cut_case() const;
};

struct ClassifierDef {
  double snap = 0.15;  // fraction of an edge; raised to kMinSnap
  static constexpr double kMinSnap = 1e-6;
};

class CutClassifier {
 public:
  // `positions` (n_vertices): the geometry the cut is computed on; it must
  // outlive the classifier and not change while it is used.
  CutClassifier(const CutPolygon& polygon, std::span<const engine::Vec3> positions, const ClassifierDef& def = {});

  // Phase 1. Declares a tet that may be cut; returns false (and forgets it)
  // when all its vertices are strictly on one side of the plane.
  bool add_candidate(const Tet& tet);
  // Phase 2: fixes the state of every vertex.
  void finalize();

  VertexState state(VertId v) const;
  bool snapped(VertId v) const;                   // "on" only because of snapping
  const std::vector<VertId>& on_vertices() const { return on_vertices_; }  // after finalize

  // Crossing of the edge (a, b): parameter from the lower id, and whether the
  // polygon crosses it (exact; cached). Only for edges that straddle.
  double crossing_parameter(VertId a, VertId b) const;
  bool crossing_covered(VertId a, VertId b) const;

  TetConfig configure(const Tet& tet) const;

  // A new point on a face, with barycentric weights on the face's vertices
  // (in the order given), so that rest and deformed positions both follow.
  struct FacePoint {
    engine::Vec3 position;
    std::array<double, 3> weights;
  };
  // Where the polygon's outline leaves the face (a, b, c): on the segment
  // from the face's active section point (a cut edge point, or a split
  // vertex) to its other section point (an uncut crossing), clamped to
  // [face_clamp, 1 - face_clamp] of it. Pass the face in a canonical order
  // (sorted ids) so that both tets sharing it compute the same bits.
  FacePoint face_point(const std::array<VertId, 3>& face) const;
  // The midpoint of the face's section segment (the 1:17 scheme's face node).
  FacePoint face_node(const std::array<VertId, 3>& face) const;

  const CutPolygon& polygon() const { return polygon_; }
  std::span<const engine::Vec3> positions() const { return positions_; }
  double snap() const { return snap_; }
  // Face points stay in [face_clamp, 1 - face_clamp] of their segment.
  double face_clamp() const { return face_clamp_; }

 private:
  struct VertexInfo {
    std::int8_t raw = 2;       // exact side, 2 = not computed
    bool on = false;           // exactly on the plane, or snapped
    bool active = false;
    double reach = 0;          // longest candidate edge at the vertex
  };
  struct EdgeInfo {
    double t = 0;              // from the lower id
    mutable std::int8_t covered = -1;  // -1 not computed yet
  };
  static std::uint64_t edge_key(VertId a, VertId b);
  std::int8_t raw_side(VertId v) const;
  // The two ends of the face's section segment (point, weights on `face`,
  // active), or false when the face is not crossed by the plane.
  struct SectionEnd {
    engine::Vec3 position;
    std::array<double, 3> weights;
    bool active;
  };
  bool section_ends(const std::array<VertId, 3>& face, SectionEnd& p, SectionEnd& q) const;

  const CutPolygon& polygon_;
  std::span<const engine::Vec3> positions_;
  double snap_;
  double face_clamp_;
  bool finalized_ = false;
  mutable std::vector<VertexInfo> info_;  // (n_vertices)
  std::unordered_map<std::uint64_t, EdgeInfo> edges_;
  std::vector<VertId> touched_;            // vertices of candidates
  std::vector<VertId> on_vertices_;
};

}  // namespace mtcut::cut
