#pragma once
// The trace of a cut on one tet, over local labels: how each of its four
// faces is triangulated, the polygon the plane cuts out of it (the section),
// the part of that section the cut actually separates (the cut surface S),
// and the uncut runs of the section (chains). Both split schemes start from
// it; it depends only on the TetConfig, so it is computed once per LUT entry.
//
// Face rules (each face decides alone, from its own three vertices, so the
// two tets sharing a face always agree):
//   - no vertex on each side: the face is kept whole;
//   - both ends of its section segment cut (edge points or split vertices):
//     split along the segment; a left-over quad takes the diagonal through
//     its corner of lower global id ("same diagonal on both sides");
//   - one end cut, the other an uncut crossing: a fan from the face point
//     where the polygon's outline crosses the face ("fans from face points");
//   - one end cut, the other an unsplit vertex on the plane: split along the
//     segment, the vertex ending the cut;
//   - neither end cut: kept whole (the polygon may poke in; ignored).

#include <array>
#include <stdexcept>
#include <vector>

#include "cut/lut/split_labels.h"
#include "engine/tet_geometry.h"

namespace mtcut::cut {

struct TraceTriangle {
  std::array<Label, 3> v;  // outward from the tet
  int face = 0;            // the tet face (opposite local vertex `face`) it lies on
  LabelSide side = LabelSide::kNone;  // kNone: it has vertices on both sides (uncut part)
};

struct SectionPoint {
  bool is_vertex = false;  // a vertex on the plane (index = local vertex), else a crossing (index = local edge)
  int index = 0;
  bool active = false;     // the cut passes here (edge point, split vertex)
};

// An uncut crossing between two face points: the tet (u, w, face_a, face_b)
// keeps the two sides joined there.
struct Bridge {
  int edge = 0;
  Label face_a = 0, face_b = 0;
};

struct CutTrace {
  TetConfig config;
  std::vector<TraceTriangle> triangles;  // the tet's boundary, all four faces
  std::vector<SectionPoint> section;     // cyclic
  std::vector<int> segment_face;         // (section) face of segment i -> i+1; -1 along a tet edge
  std::vector<Label> surface;            // S, cyclic; copied points are unsided here
  std::vector<std::vector<int>> chains;  // runs of inactive section points (indices into `section`)
  std::vector<Bridge> bridges;           // the chains that are one uncut crossing
  bool long_chain = false;               // some chain has 2 or more points
  std::array<bool, 4> face_point{};      // faces holding a (single) face point
  std::array<bool, 4> face_node{};       // 1:17 only: faces holding a split node

  bool complete() const { return chains.empty(); }
};

struct TraceOptions {
  // The 1:17 scheme's generic rule: a node (one copy per side) on every face
  // the cut runs across, instead of splitting the face along the segment.
  bool split_face_nodes = false;
};

// Requires config.is_cut().
CutTrace trace_cut(const TetConfig& config, const TraceOptions& options = {});

// Label helpers for a configuration.
LabelSide label_side_in(const TetConfig& config, Label l);  // side of strict vertices and of copies
bool is_copied(const TetConfig& config, Label l);           // one copy per side (edge points, split vertices)
bool on_cut_surface(const TetConfig& config, Label l);
bool on_tet_face(Label l, int face);                        // lies on the face opposite local vertex `face`
// Local edge index of (a, b); constexpr for the tables built at compile time.
constexpr int edge_between(int a, int b) {
  for (int k = 0; k < 6; ++k)
    if ((engine::kTetEdges[k][0] == a && engine::kTetEdges[k][1] == b) ||
        (engine::kTetEdges[k][0] == b && engine::kTetEdges[k][1] == a))
      return k;
  throw std::logic_error("edge_between: not an edge");
}

}  // namespace mtcut::cut
