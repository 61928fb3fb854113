#include "cut/lut/cut_trace.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "engine/tet_geometry.h"

namespace mtcut::cut {
namespace {

using engine::kTetEdges;
using engine::kTetFaces;

constexpr Label vertex_label(int i, LabelSide s = LabelSide::kNone) { return make_label(LabelKind::kVertex, i, s); }
constexpr Label edge_label(int k, LabelSide s) { return make_label(LabelKind::kEdge, k, s); }
constexpr Label face_label(int f, LabelSide s = LabelSide::kNone) { return make_label(LabelKind::kFace, f, s); }

// A point of a face's boundary walk; `point` identifies the geometric point
// (copies of one point share it).
struct WalkEntry {
  Label label;
  int point;
};

LabelSide triangle_side(const TetConfig& c, const std::array<Label, 3>& t) {
  bool neg = false, pos = false;
  for (Label l : t) {
    const LabelSide s = label_side_in(c, l);
    neg |= s == LabelSide::kNeg;
    pos |= s == LabelSide::kPos;
  }
  if (neg && pos) return LabelSide::kNone;
  return neg ? LabelSide::kNeg : pos ? LabelSide::kPos : LabelSide::kNone;
}

class Tracer {
 public:
  Tracer(const TetConfig& config, const TraceOptions& options) : options_(options) { trace_.config = config; }

  CutTrace run() {
    for (int f = 0; f < 4; ++f) triangulate_face(f);
    build_section();
    return std::move(trace_);
  }

 private:
  const TetConfig& c() const { return trace_.config; }

  bool two_sided(int f) const {
    bool neg = false, pos = false;
    for (int v : kTetFaces[f]) {
      neg |= c().vertex[v] == VertexState::kNeg;
      pos |= c().vertex[v] == VertexState::kPos;
    }
    return neg && pos;
  }

  // Emits a triangle, giving unsided split vertices the triangle's side.
  void emit(int f, std::array<Label, 3> t) {
    const LabelSide side = triangle_side(c(), t);
    for (Label& l : t)
      if (label_kind(l) == LabelKind::kVertex && c().vertex[label_index(l)] == VertexState::kOnActive &&
          label_side(l) == LabelSide::kNone) {
        if (side == LabelSide::kNone) throw std::logic_error("cut trace: a split vertex in an uncut triangle");
        l = with_side(l, side);
      }
    trace_.triangles.push_back({t, f, side});
  }

  void emit_fan(int f, Label apex, const std::vector<WalkEntry>& walk) {
    const std::size_t n = walk.size();
    for (std::size_t j = 0; j < n; ++j) {
      const WalkEntry& a = walk[j];
      const WalkEntry& b = walk[(j + 1) % n];
      if (a.point == b.point) continue;  // two copies of one point
      std::array<Label, 3> t = {apex, a.label, b.label};
      if (label_side(apex) != LabelSide::kNone) {  // a split node takes the triangle's side
        t[0] = unsided(apex);
        const LabelSide side = triangle_side(c(), t);
        t[0] = with_side(apex, side);
      }
      emit(f, t);
    }
  }

  void emit_polygon(int f, const std::vector<WalkEntry>& poly) {
    if (poly.size() == 3) {
      emit(f, {poly[0].label, poly[1].label, poly[2].label});
      return;
    }
    if (poly.size() != 4) throw std::logic_error("cut trace: unexpected face piece of " + std::to_string(poly.size()));
    // (P, v, w, Q): the diagonal goes through the strict corner of lower id.
    const int v = label_index(poly[1].label), w = label_index(poly[2].label);
    if (c().rank[v] < c().rank[w]) {
      emit(f, {poly[0].label, poly[1].label, poly[3].label});
      emit(f, {poly[1].label, poly[2].label, poly[3].label});
    } else {
      emit(f, {poly[0].label, poly[1].label, poly[2].label});
      emit(f, {poly[0].label, poly[2].label, poly[3].label});
    }
  }

  void triangulate_face(int f) {
    const auto& corners = kTetFaces[f];
    if (!two_sided(f)) {
      emit(f, {vertex_label(corners[0]), vertex_label(corners[1]), vertex_label(corners[2])});
      return;
    }
    // Boundary walk with edge-point copies, and the section ends on this face.
    std::vector<WalkEntry> walk;
    struct End {
      bool is_vertex;
      int index;
      bool active;
      int first, last;  // walk indices of its copies (equal for one entry)
    };
    std::vector<End> ends;
    for (int j = 0; j < 3; ++j) {
      const int x = corners[j], y = corners[(j + 1) % 3];
      const VertexState sx = c().vertex[x];
      if (is_on(sx))
        ends.push_back({true, x, sx == VertexState::kOnActive, static_cast<int>(walk.size()),
                        static_cast<int>(walk.size())});
      walk.push_back({vertex_label(x), x});
      const int k = edge_between(x, y);
      if (c().straddles(k)) {
        const bool active = c().edge_active(k);
        const int at = static_cast<int>(walk.size());
        if (active) {
          walk.push_back({edge_label(k, side_of(sx)), 4 + k});
          walk.push_back({edge_label(k, side_of(c().vertex[y])), 4 + k});
        }
        ends.push_back({false, k, active, at, active ? at + 1 : at});
      }
    }
    if (ends.size() != 2) throw std::logic_error("cut trace: a two-sided face without two section ends");
    End p = ends[0], q = ends[1];
    if (!p.active && !q.active) {
      emit(f, {vertex_label(corners[0]), vertex_label(corners[1]), vertex_label(corners[2])});
      return;
    }
    if (p.active != q.active && (p.active ? !q.is_vertex : !p.is_vertex)) {
      // One cut end, one uncut crossing: fan from the face point.
      trace_.face_point[f] = true;
      emit_fan(f, face_label(f), walk);
      return;
    }
    if (options_.split_face_nodes) {
      // 1:17: a node on the segment, one copy per side, and a fan from it.
      trace_.face_node[f] = true;
      std::vector<WalkEntry> fan;
      for (const WalkEntry& e : walk) fan.push_back(e);
      emit_fan(f, face_label(f, LabelSide::kNeg), fan);
      return;
    }
    // Split along the segment. A split vertex is doubled in the walk so each
    // side gets its copy; an unsplit vertex on the plane is shared.
    auto split_vertex_copies = [&](End& e) {
      if (!e.is_vertex || !e.active) return;
      const int i = e.first;
      const int n = static_cast<int>(walk.size());
      // The neighbours of a vertex end in the walk are the face's two other
      // corners, one on each side.
      const VertexState sp = c().vertex[label_index(walk[(i + n - 1) % n].label)];
      walk[i].label = vertex_label(e.index, side_of(sp));
      walk.insert(walk.begin() + i + 1, {vertex_label(e.index, opposite(side_of(sp))), e.index});
      e.last = i + 1;
      if (q.first > i && &e == &p) {
        q.first += 1;
        q.last += 1;
      }
    };
    split_vertex_copies(p);
    split_vertex_copies(q);
    const int m = static_cast<int>(walk.size());
    auto piece = [&](int from, int to) {
      std::vector<WalkEntry> out;
      for (int i = from;; i = (i + 1) % m) {
        out.push_back(walk[i]);
        if (i == to) break;
      }
      return out;
    };
    emit_polygon(f, piece(p.last, q.first));
    emit_polygon(f, piece(q.last, p.first));
  }

  void build_section() {
    // Points: vertices on the plane, then straddling edges.
    std::vector<SectionPoint> points;
    for (int v = 0; v < 4; ++v)
      if (is_on(c().vertex[v])) points.push_back({true, v, c().vertex[v] == VertexState::kOnActive});
    for (int k = 0; k < 6; ++k)
      if (c().straddles(k)) points.push_back({false, k, c().edge_active(k)});
    auto find_point = [&](bool is_vertex, int index) {
      for (std::size_t i = 0; i < points.size(); ++i)
        if (points[i].is_vertex == is_vertex && points[i].index == index) return static_cast<int>(i);
      throw std::logic_error("cut trace: missing section point");
    };
    // Segments: one per two-sided face, one per tet edge lying in the plane.
    struct Segment {
      int a, b, face;
    };
    std::vector<Segment> segments;
    for (int f = 0; f < 4; ++f) {
      if (!two_sided(f)) continue;
      std::vector<int> ends;
      for (int v : kTetFaces[f])
        if (is_on(c().vertex[v])) ends.push_back(find_point(true, v));
      for (int j = 0; j < 3; ++j) {
        const int k = edge_between(kTetFaces[f][j], kTetFaces[f][(j + 1) % 3]);
        if (c().straddles(k)) ends.push_back(find_point(false, k));
      }
      segments.push_back({ends[0], ends[1], f});
    }
    for (int k = 0; k < 6; ++k)
      if (is_on(c().vertex[kTetEdges[k][0]]) && is_on(c().vertex[kTetEdges[k][1]]))
        segments.push_back({find_point(true, kTetEdges[k][0]), find_point(true, kTetEdges[k][1]), -1});
    if (points.size() < 3 || segments.size() != points.size())
      throw std::logic_error("cut trace: the section is not a polygon");

    // Walk the cycle, starting at an active point.
    int start = 0;
    while (start < static_cast<int>(points.size()) && !points[start].active) ++start;
    if (start == static_cast<int>(points.size())) throw std::logic_error("cut trace: nothing is cut");
    std::vector<bool> used(segments.size(), false);
    int at = start;
    do {
      trace_.section.push_back(points[at]);
      int next = -1;
      for (std::size_t s = 0; s < segments.size() && next < 0; ++s) {
        if (used[s] || (segments[s].a != at && segments[s].b != at)) continue;
        used[s] = true;
        next = segments[s].a == at ? segments[s].b : segments[s].a;
        trace_.segment_face.push_back(segments[s].face);
      }
      if (next < 0) throw std::logic_error("cut trace: the section is open");
      at = next;
    } while (at != start);
    if (trace_.section.size() != points.size()) throw std::logic_error("cut trace: the section has two loops");

    const int n = static_cast<int>(trace_.section.size());
    const auto& sec = trace_.section;
    auto point_label = [&](const SectionPoint& p) {
      return p.is_vertex ? vertex_label(p.index) : edge_label(p.index, LabelSide::kNone);
    };
    // The contour point on the segment i -> i+1 whose one end is uncut.
    auto contour = [&](int i) {
      const SectionPoint& x = sec[i].active ? sec[(i + 1) % n] : sec[i];
      return x.is_vertex ? vertex_label(x.index) : face_label(trace_.segment_face[i]);
    };
    // Chains of inactive points (the walk starts at an active one).
    for (int i = 0; i < n;) {
      if (sec[i].active) {
        ++i;
        continue;
      }
      std::vector<int> chain;
      while (i < n && !sec[i].active) chain.push_back(i++);
      trace_.long_chain |= chain.size() >= 2;
      if (chain.size() == 1 && !sec[chain[0]].is_vertex) {
        const int j = chain[0];
        trace_.bridges.push_back({sec[j].index, face_label(trace_.segment_face[(j + n - 1) % n]),
                                  face_label(trace_.segment_face[j])});
      }
      trace_.chains.push_back(std::move(chain));
    }
    // The cut surface: cut points in order, each uncut run replaced by its
    // two contour points.
    auto& s = trace_.surface;
    for (int i = 0; i < n; ++i) {
      if (sec[i].active) {
        s.push_back(point_label(sec[i]));
        continue;
      }
      if (sec[(i + n - 1) % n].active) s.push_back(contour((i + n - 1) % n));
      if (sec[(i + 1) % n].active) {
        const Label l = contour(i);
        if (s.empty() || s.back() != l) s.push_back(l);
      }
    }
    if (s.size() > 1 && s.front() == s.back()) s.pop_back();
  }

  CutTrace trace_;
  TraceOptions options_;
};

}  // namespace

LabelSide label_side_in(const TetConfig& config, Label l) {
  if (label_kind(l) == LabelKind::kVertex) {
    const VertexState s = config.vertex[label_index(l)];
    if (is_strict(s)) return side_of(s);
  }
  return label_side(l);
}

bool is_copied(const TetConfig& config, Label l) {
  switch (label_kind(l)) {
    case LabelKind::kVertex: return config.vertex[label_index(l)] == VertexState::kOnActive;
    case LabelKind::kEdge: return true;
    default: return false;
  }
}

bool on_cut_surface(const TetConfig& config, Label l) {
  return label_kind(l) != LabelKind::kVertex || is_on(config.vertex[label_index(l)]);
}

bool on_tet_face(Label l, int face) {
  switch (label_kind(l)) {
    case LabelKind::kVertex: return label_index(l) != face;
    case LabelKind::kEdge: {
      const int k = label_index(l);
      return kTetEdges[k][0] != face && kTetEdges[k][1] != face;
    }
    case LabelKind::kFace: return label_index(l) == face;
    case LabelKind::kCentre: return false;
  }
  return false;
}

CutTrace trace_cut(const TetConfig& config, const TraceOptions& options) {
  if (!config.is_cut()) throw std::logic_error("trace_cut: the tet is not cut");
  return Tracer(config, options).run();
}

}  // namespace mtcut::cut
