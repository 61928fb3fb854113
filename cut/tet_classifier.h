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
//   kOnInactive    on the plane, not split, the cut ending at it: supported
//                  by the split rules; produced only for the front an
//                  earlier step of a stroke left on its sheet (a
//                  continuation, stroke_junction.h). Other such vertices
//                  are kept off the cut instead (below).
// A vertex is "on" when it is exactly on the plane, or when a straddling edge
// of a candidate tet meets the plane within `snap` (a fraction of the edge)
// of it, and it projects into the polygon grown by (snap + face_clamp) times
// its longest edge (so that a stroke continuing an incision splits the face
// points the previous stroke left near its outline). The vertex is not
// moved: the cut surface bends through it. A vertex that would be on but
// lies off the polygon (or is vetoed) is kept off the cut: it keeps its side,
// or when it lies on the plane (to rounding) the side its neighbours lean to
// (a copy made by an earlier cut in this plane goes with its tets), and cut
// points stay `snap` away from it. Hence every cut point lies in
// [snap, 1 - snap] of its edge, and no sliver is made (DESIGN.md,
// "Degenerate contacts").

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "absl/container/flat_hash_map.h"
#include "cut/cut_polygon.h"
#include "cut/stroke_junction.h"
#include "engine/tet_mesh.h"
#include "engine/validation.h"

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
  // The cut surface may leave the plane: a vertex is on the cut (snapped,
  // not moved) or kept off it (cut points moved away). Then both sides must
  // triangulate it the same way.
  bool bent = false;

  bool straddles(int edge) const;
  bool edge_active(int edge) const { return straddles(edge) && (covered >> edge & 1); }
  // Split needed: an edge crossed inside the polygon, or the cut passing
  // through a vertex into a tet that has vertices on both sides.
  bool is_cut() const;
  // 8 bits of states, 6 of coverage (straddling edges only), 5 of id order,
  // 1 for a bent cut surface (implied by a vertex on the cut).
  std::uint32_t key() const;
  CutCase cut_case() const;
};

struct ClassifierDef {
  double snap = 0.15;  // fraction of an edge; raised to kMinSnap
  static constexpr double kMinSnap = 1e-6;

  static double effective_snap(double snap) { return std::clamp(snap, kMinSnap, 0.45); }
  static double face_clamp(double snap) { return std::clamp(snap, 0.25, 0.45); }
  // How far off the polygon (times the vertex's longest edge) a vertex on
  // the plane may be and still be split.
  static double margin_fraction(double snap) { return effective_snap(snap) + face_clamp(snap); }
};

class CutClassifier {
 private:
  struct VertexInfo {
    std::int8_t raw = 2;       // exact side, 2 = not computed (then `distance` is not either)
    bool on = false;           // exactly on the plane, or snapped
    bool active = false;
    bool vetoed = false;       // kept off the cut
    bool requested_off = false;  // by veto()
    bool pulled = false;       // on the cut by request
    bool crack_sided = false;  // behind a stroke's junction, made by the stroke: sided by its crack
    bool crack_end = false;    // a stroke's front on its sheet, off the polygon: kOnInactive
    std::int8_t kept_side = 0; // side of a vertex kept off the cut (0: its raw side)
    double lean = 0;           // sum of its candidate neighbours' distances to the plane
    double reach2 = 0;         // squared length of the longest candidate edge at the vertex
    double distance = 0;       // signed distance to the plane (with `raw`)
    bool dirty = false;        // listed in the scratch's `dirty` (to be reset)

    bool operator==(const VertexInfo&) const = default;
  };

 public:
  // Per-vertex storage reused from one classifier to the next: a classifier
  // costs what its cut touches, not the mesh's vertex count (a per-frame
  // cut touches a few hundred of tens of thousands of vertices). It grows to
  // the largest mesh seen; a classifier resets the entries it wrote when it
  // is destroyed. One classifier at a time.
  class Scratch {
   public:
    // Handed back clean: no classifier holds it, every entry is pristine.
    engine::ValidationReport validate() const;
    // Room for a mesh of `vertices` (between classifiers), so that none
    // grows it.
    void reserve(std::size_t vertices);

   private:
    friend class CutClassifier;
    std::vector<VertexInfo> info;  // pristine (default) except while a classifier writes
    std::vector<VertId> dirty;     // entries written by the live classifier
    // After finalize, for the candidates' vertices: 1 + state | vetoed << 2
    // (0 = not coded). A byte per vertex: the configuration of every
    // candidate reads four, which the 48-byte records would scatter.
    std::vector<std::uint8_t> code;
    bool in_use = false;
  };

  // `positions` (n_vertices): the geometry the cut is computed on; it must
  // outlive the classifier and not change while it is used.
  // `scratch`: reused storage (nullptr: the classifier allocates its own,
  // a pass over the vertices). `continuation`: the polygon is a step of a
  // scalpel stroke (cut/stroke_junction.h): behind the junction with the
  // last step, vertices are sided by the stroke's crack and earlier planes,
  // the crack's front on the junction is split, and face points on the
  // polygon's leading edge are not clamped. It must outlive the classifier.
  CutClassifier(const CutPolygon& polygon, std::span<const engine::Vec3> positions, const ClassifierDef& def = {},
                Scratch* scratch = nullptr, const CutContinuation* continuation = nullptr);
  ~CutClassifier();
  CutClassifier(const CutClassifier&) = delete;
  CutClassifier& operator=(const CutClassifier&) = delete;

  // Phase 0 (optional): `v` must not be snapped onto the cut: cut points near
  // it stay `snap` away from it instead, and if it lies exactly on the plane
  // it counts as positive. The cutter vetoes vertices whose split would pinch
  // the mesh (two parts of one side touching along an edge).
  void veto(VertId v);
  // Phase 0 (optional): `v` is on the cut and split, however far its edges
  // meet the plane and however far off the polygon it is (not after veto()).
  void pull_in(VertId v);

  // Room for the straddling edges of `candidates` tets: one per tet, as tets
  // share their edges (Table 1's cuts and the stress scenario's meet 0.4 to
  // 0.9 per candidate), so the edge table is not rehashed again and again as
  // it fills (Table 1's largest cut meets thousands).
  void expect_candidates(std::size_t candidates) {
    edges_.reserve(candidates);
    edge_t_.reserve(candidates);
  }
  // Phase 1. Declares a tet that may be cut; returns false (and forgets it)
  // when all its vertices are strictly on one side of the plane.
  bool add_candidate(const Tet& tet);
  // What add_candidate would return, with no effect: a search can drop the
  // tets that cannot be cut before it sorts the rest (after phase 0).
  bool may_be_cut(const Tet& tet) const;
  // Phase 1: the vertices that the candidates so far put on the cut (on the
  // plane, or snapped), each returned once, in the order they were met. The
  // cut may pass through them, so every tet around them must be classified:
  // a search adds those tets as candidates, until none is returned.
  std::vector<VertId> take_new_on_vertices();
  // Phase 1: `v` is on the cut so far (finalize() may still keep it off).
  bool on_so_far(VertId v) const { return at(v).on; }
  // Phase 2: fixes the state of every vertex.
  void finalize();

  VertexState state(VertId v) const {
    const std::uint8_t code = scratch_->code[v.index()];
    return code != 0 ? static_cast<VertexState>((code - 1) & 3) : uncoded_state(v);
  }
  bool snapped(VertId v) const;                   // "on" only because of snapping
  bool vetoed(VertId v) const;          // kept off the cut (requested or found off the polygon)
  bool veto_requested(VertId v) const;  // by veto()
  const std::vector<VertId>& on_vertices() const { return on_vertices_; }  // after finalize
  // Vertices on the plane (to rounding) but kept off the cut, sided by their
  // neighbours rather than by the sign of their distance (after finalize).
  const std::vector<VertId>& resided_vertices() const { return resided_; }

  // Crossing of the edge (a, b): parameter from the lower id, and whether the
  // polygon crosses it (exact; cached). Only for edges that straddle.
  double crossing_parameter(VertId a, VertId b) const;
  // The same for the edge configure numbered `number` (no look-up by ends).
  double crossing_parameter_of(std::int32_t number) const {
    return std::clamp(edge_t_[static_cast<std::size_t>(number)], snap_, 1 - snap_);
  }
  bool crossing_covered(VertId a, VertId b) const;

  TetConfig configure(const Tet& tet) const;
  // The same, and the number of each local edge (kTetEdges) that straddles
  // the plane, -1 for the others: straddling edges are numbered 0, 1, ... as
  // the classifier first meets them, so a caller can keep per-edge data (the
  // cut points on it) in an array instead of a map keyed by its ends.
  TetConfig configure(const Tet& tet, std::array<std::int32_t, 6>& edge_numbers) const;
  // Edges numbered so far (an upper bound of the numbers configure gives).
  std::size_t edges_numbered() const { return edges_.size(); }
  // The side a tet that is not cut lies on (after finalize): the side of its
  // strict vertices, or, when all four are on the cut, the side its vertices
  // lean to.
  VertexState side_of_uncut(const Tet& tet) const;

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
  struct EdgeInfo {
    std::int32_t number = 0;   // in the order edges are met; its parameter is edge_t_[number]
    std::int8_t covered = -1;  // -1 not computed yet
  };
  static std::uint64_t edge_key(VertId a, VertId b);
  // The entry of edge (a, b), made (numbered, its parameter computed) the
  // first time.
  EdgeInfo& edge(VertId a, VertId b) const;
  // Whether the polygon crosses edge (a, b) of entry e (computed once).
  bool covered(EdgeInfo& e, VertId a, VertId b) const;
  std::int8_t raw_side(VertId v) const {
    const std::int8_t raw = at(v).raw;
    return raw != 2 ? raw : compute_side(v);
  }
  std::int8_t compute_side(VertId v) const;  // raw_side's first time: caches side and distance
  double distance(VertId v) const;  // signed distance to the plane (cached with raw_side)
  double reach(VertId v) const { return std::sqrt(at(v).reach2); }
  const VertexInfo& at(VertId v) const { return scratch_->info[v.index()]; }
  // v's entry, to write (listed for the reset on first write).
  VertexInfo& edit(VertId v) const {
    VertexInfo& info = scratch_->info[v.index()];
    if (!info.dirty) {
      info.dirty = true;
      scratch_->dirty.push_back(v);
    }
    return info;
  }
  std::int8_t side_for_crossings(VertId v) const;
  VertexState uncoded_state(VertId v) const;  // state() from the record (before finalize, or off the candidates)
  bool coded_vetoed(VertId v) const {  // vetoed(), from the code when there is one
    const std::uint8_t code = scratch_->code[v.index()];
    return code != 0 ? (code >> 2 & 1) != 0 : at(v).vetoed;
  }
  // side_for_crossings of each vertex; all strictly on one side.
  std::array<std::int8_t, 4> crossing_sides(const Tet& tet) const;
  static bool one_sided(const std::array<std::int8_t, 4>& sides);
  double raw_parameter(VertId a, VertId b) const;
  void keep_off(VertId v);
  void put_on(VertId v);  // phase 1: marks v on (recorded in new_on_)
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
  const CutContinuation* continuation_;
  double snap_;
  double face_clamp_;
  bool finalized_ = false;
  std::unique_ptr<Scratch> own_scratch_;  // when none was given
  Scratch* scratch_;                      // info: (>= n_vertices) entries
  mutable absl::flat_hash_map<std::uint64_t, EdgeInfo> edges_;  // straddling edges met so far
  mutable std::vector<double> edge_t_;  // (edges_) each numbered edge's crossing parameter from its lower id
  std::vector<VertId> touched_;            // vertices of candidates
  std::vector<VertId> new_on_;             // put on since take_new_on_vertices()
  std::vector<VertId> on_vertices_;
  std::vector<VertId> resided_;
};

}  // namespace mtcut::cut
