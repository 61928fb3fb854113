#include "cut/lut/split_lut.h"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "cut/lut/piece_filler.h"
#include "engine/tet_geometry.h"

namespace mtcut::cut {
namespace {

using engine::kTetEdges;
using Tet4 = std::array<Label, 4>;
using Tri = std::array<Label, 3>;

// A boundary triangle of a piece and the plane it lies in: 0..3 the tet's
// faces, 5 + b the interface with bridge b.
struct PieceTri {
  Tri v;
  int plane;
};

bool contains(const Tri& t, Label a) { return t[0] == a || t[1] == a || t[2] == a; }

// How the cut surface S is triangulated: fanned from one of its corners
// (shared by both pieces), from the centre (a new point, split in two), or
// left to each piece (when S is planar any two triangulations fit).
struct SurfaceFan {
  enum Kind { kFree, kCorner, kCentre } kind = kFree;
  int corner = 0;  // index into S
};

class LutSplitter {
 public:
  explicit LutSplitter(const TetConfig& config)
      : c_(config),
        tr_(trace_cut(config)),
        bends_(config.bent || std::any_of(config.vertex.begin(), config.vertex.end(), is_on)) {}

  SplitRecipe run() {
    SplitRecipe recipe;
    recipe.kind = c_.cut_case();
    std::optional<std::vector<Tet4>> best;
    bool centre = false;
    if (!tr_.long_chain) best = by_pieces(&centre);
    if (tr_.chains.size() == 1) {
      auto cone = by_single_cone();
      if (cone && (!best || cone->size() < best->size())) {
        best = std::move(cone);
        centre = false;
      }
    }
    if (!best) {
      // Last resort, always valid: a cone from the centre of the cut surface
      // over the whole boundary (the 1:17 reference's construction).
      best = by_centre_cone();
      centre = true;
    }
    if (!best) throw std::logic_error("generate_lut_split: no decomposition for configuration " + std::to_string(c_.key()));
    recipe.tets = std::move(*best);
    if (centre) recipe.centre_of = tr_.surface;
    return recipe;
  }

 private:
  // The realisations every tet must be positive in. A planar cut needs no
  // check (its pieces are convex); a vertex on the cut may be off the plane
  // (snapped), so then cut points are also placed anywhere on their edges
  // and faces.
  const std::vector<LabelPositions>& where() {
    if (where_.empty()) {
      where_.push_back(reference());
      std::mt19937_64 rng(0x5eed);
      for (int i = 0; i < (bends_ ? 32 : 12); ++i) where_.push_back(random_positions(c_, tr_, rng, !bends_ || i % 3 == 0));
    }
    return where_;
  }

  const LabelPositions& reference() {
    if (!reference_) reference_ = reference_positions(c_, tr_);
    return *reference_;
  }

  // Orients the tets in the reference realisation; true when they hold.
  bool holds(std::vector<Tet4>& tets) {
    const LabelPositions& ref = reference();
    for (Tet4& t : tets)
      if (volume6(ref[t[0]], ref[t[1]], ref[t[2]], ref[t[3]]) < 0) std::swap(t[2], t[3]);
    if (!bends_) return true;
    for (const LabelPositions& p : where()) {
      auto corner = [&](int i) { return p[make_label(LabelKind::kVertex, i)]; };
      const double whole = volume6(corner(0), corner(1), corner(2), corner(3));
      for (const Tet4& t : tets)
        if (!(volume6(p[t[0]], p[t[1]], p[t[2]], p[t[3]]) > 1e-14 * whole)) return false;
    }
    return true;
  }

  std::vector<Label> surface(LabelSide side) const {
    std::vector<Label> s;
    for (Label l : tr_.surface) s.push_back(is_copied(c_, l) ? with_side(l, side) : l);
    return s;
  }

  // A fan of S from corner p must not join two single points across S:
  // the two sides would stay glued along that diagonal.
  bool fan_allowed(const std::vector<Label>& s, int p) const {
    const int n = static_cast<int>(s.size());
    if (is_copied(c_, s[p])) return true;
    for (int j = 0; j < n; ++j)
      if (j != p && j != (p + 1) % n && j != (p + n - 1) % n && !is_copied(c_, s[j])) return false;
    return true;
  }

  std::vector<Tri> fan(const std::vector<Label>& s, int p) const {
    std::vector<Tri> out;
    const int n = static_cast<int>(s.size());
    for (int j = 1; j + 1 < n; ++j) out.push_back({s[p], s[(p + j) % n], s[(p + j + 1) % n]});
    return out;
  }

  std::vector<PieceTri> piece_triangles(LabelSide side) const {
    std::vector<PieceTri> tris;
    for (const TraceTriangle& t : tr_.triangles)
      if (t.side == side) tris.push_back({t.v, t.face});
    for (std::size_t b = 0; b < tr_.bridges.size(); ++b) {
      const int k = tr_.bridges[b].edge;
      const int u = side_of(c_.vertex[kTetEdges[k][0]]) == side ? kTetEdges[k][0] : kTetEdges[k][1];
      tris.push_back({{make_label(LabelKind::kVertex, u), tr_.bridges[b].face_a, tr_.bridges[b].face_b},
                      5 + static_cast<int>(b)});
    }
    return tris;
  }

  // The cone from `apex` over a piece, or nullopt when the apex does not see
  // every triangle (one lies in a plane through it without touching it).
  std::optional<std::vector<Tet4>> cone(const std::vector<PieceTri>& tris, const std::vector<Label>& s, Label apex,
                                        const SurfaceFan& sf) const {
    std::vector<Tet4> out;
    for (const PieceTri& t : tris) {
      if (contains(t.v, apex)) continue;
      if (t.plane < 4 && on_tet_face(apex, t.plane)) return std::nullopt;
      out.push_back({apex, t.v[0], t.v[1], t.v[2]});
    }
    const auto at = std::find(s.begin(), s.end(), apex);
    if (at != s.end()) {
      // The apex is on S: S must be the fan from it.
      const int i = static_cast<int>(at - s.begin());
      if (sf.kind == SurfaceFan::kCorner && sf.corner != i && s.size() > 3) return std::nullopt;
      if (!fan_allowed(s, i)) return std::nullopt;
      return out;
    }
    if (on_cut_surface(c_, apex)) return std::nullopt;
    int p = sf.kind == SurfaceFan::kCorner ? sf.corner : 0;
    if (sf.kind == SurfaceFan::kFree) {
      while (p < static_cast<int>(s.size()) && !is_copied(c_, s[p])) ++p;
      if (p == static_cast<int>(s.size())) return std::nullopt;
    }
    for (const Tri& t : fan(s, p)) out.push_back({apex, t[0], t[1], t[2]});
    return out;
  }

  // The cheapest cone over a piece (ties: lowest label) that holds.
  std::optional<std::vector<Tet4>> best_cone(LabelSide side, const SurfaceFan& sf) {
    const std::vector<PieceTri> tris = piece_triangles(side);
    const std::vector<Label> s = surface(side);
    std::vector<Label> candidates(s.begin(), s.end());
    for (const PieceTri& t : tris) candidates.insert(candidates.end(), t.v.begin(), t.v.end());
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    std::optional<std::vector<Tet4>> best;
    for (Label a : candidates) {
      auto tets = cone(tris, s, a, sf);
      if (!tets || (best && tets->size() >= best->size())) continue;
      if (holds(*tets)) best = std::move(tets);
    }
    return best;
  }

  // A piece no cone fits, filled by search (piece_filler.h). Its boundary:
  // its faces, the bridge interfaces and S, each oriented away from it.
  std::optional<std::vector<Tet4>> fill(LabelSide side, const SurfaceFan& sf) {
    const LabelPositions& ref = reference();
    Label other = 0;  // a point on the other side of the cut
    for (int v = 0; v < 4; ++v)
      if (is_strict(c_.vertex[v]) && side_of(c_.vertex[v]) != side) other = make_label(LabelKind::kVertex, v);
    auto away = [&](Tri t, const engine::Vec3& outside) {
      const engine::Vec3 n = (ref[t[1]] - ref[t[0]]).cross(ref[t[2]] - ref[t[0]]);
      if (n.dot(outside - ref[t[0]]) < 0) std::swap(t[1], t[2]);
      return t;
    };
    std::vector<Tri> boundary;
    for (const PieceTri& t : piece_triangles(side)) {
      if (t.plane < 4) {
        boundary.push_back(t.v);  // the tet's faces are already outward
        continue;
      }
      const Bridge& b = tr_.bridges[static_cast<std::size_t>(t.plane - 5)];
      const int u = kTetEdges[b.edge][0], w = kTetEdges[b.edge][1];
      const int far = side_of(c_.vertex[u]) == side ? w : u;  // the bridge's corner outside the piece
      boundary.push_back(away(t.v, ref[make_label(LabelKind::kVertex, far)]));
    }
    const std::vector<Label> s = surface(side);
    const std::size_t n = s.size();
    if (sf.kind == SurfaceFan::kCentre) {
      const Label centre = make_label(LabelKind::kCentre, 0, side);
      for (std::size_t j = 0; j < n; ++j) boundary.push_back(away({centre, s[j], s[(j + 1) % n]}, ref[other]));
    } else {
      int p = sf.corner;
      if (sf.kind == SurfaceFan::kFree) {
        p = 0;
        while (p < static_cast<int>(n) && !is_copied(c_, s[p])) ++p;
        if (p == static_cast<int>(n)) return std::nullopt;
      }
      for (const Tri& t : fan(s, p)) boundary.push_back(away(t, ref[other]));
    }
    // Without a new point a filling rarely exists when no cone fits: search
    // briefly; with the centre, long enough to find one.
    return fill_piece(boundary, where(), 12, sf.kind == SurfaceFan::kCentre ? 50000 : 2000);
  }

  std::optional<std::vector<Tet4>> piece(LabelSide side, const SurfaceFan& sf) {
    auto tets = best_cone(side, sf);
    if (!tets && sf.kind != SurfaceFan::kCentre) tets = fill(side, sf);
    if (!tets && sf.kind == SurfaceFan::kCentre) tets = fill(side, sf);
    return tets;
  }

  // Steps 2, 3 and 5: bridges, then the two pieces.
  std::optional<std::vector<Tet4>> by_pieces(bool* centre) {
    std::vector<Tet4> bridges;
    for (const Bridge& b : tr_.bridges) {
      const int u = kTetEdges[b.edge][0], w = kTetEdges[b.edge][1];
      bridges.push_back({make_label(LabelKind::kVertex, u), make_label(LabelKind::kVertex, w), b.face_a, b.face_b});
    }
    // Fans of S to try: free when S is planar (or a triangle), else shared.
    std::vector<SurfaceFan> fans;
    if (!bends_ || tr_.surface.size() == 3) {
      fans.push_back({SurfaceFan::kFree, 0});
    } else {
      for (int p = 0; p < static_cast<int>(tr_.surface.size()); ++p)
        if (fan_allowed(tr_.surface, p)) fans.push_back({SurfaceFan::kCorner, p});
    }
    std::optional<std::vector<Tet4>> best;
    for (const SurfaceFan& sf : fans) {
      auto neg = piece(LabelSide::kNeg, sf);
      auto pos = neg ? piece(LabelSide::kPos, sf) : std::nullopt;
      if (!neg || !pos || (best && neg->size() + pos->size() + bridges.size() >= best->size())) continue;
      best = bridges;
      best->insert(best->end(), neg->begin(), neg->end());
      best->insert(best->end(), pos->begin(), pos->end());
    }
    if (best) return best;
    // No filling without a new point keeps the sides apart (case O): the
    // centre of S, split in two.
    const SurfaceFan centre_fan{SurfaceFan::kCentre, 0};
    auto neg = fill(LabelSide::kNeg, centre_fan);
    auto pos = neg ? fill(LabelSide::kPos, centre_fan) : std::nullopt;
    if (!neg || !pos) return std::nullopt;
    *centre = true;
    best = bridges;
    best->insert(best->end(), neg->begin(), neg->end());
    best->insert(best->end(), pos->begin(), pos->end());
    return best;
  }

  // Step 4: one cone over the whole boundary from a contour point. S comes
  // out as the fan from the apex on both sides.
  std::optional<std::vector<Tet4>> by_single_cone() {
    std::optional<std::vector<Tet4>> best;
    for (Label apex : tr_.surface) {
      if (is_copied(c_, apex)) continue;
      std::vector<Tet4> tets;
      bool valid = true;
      for (const TraceTriangle& t : tr_.triangles) {
        if (contains(t.v, apex)) continue;
        if (on_tet_face(apex, t.face)) {
          valid = false;
          break;
        }
        tets.push_back({apex, t.v[0], t.v[1], t.v[2]});
      }
      if (!valid || (best && tets.size() >= best->size())) continue;
      if (holds(tets)) best = std::move(tets);
    }
    return best;
  }

  // A cone from the centre over every boundary triangle; the centre is split
  // when nothing joins the sides inside the tet (the cut ends at it otherwise).
  std::optional<std::vector<Tet4>> by_centre_cone() {
    bool split = true;
    for (const SectionPoint& p : tr_.section) split &= p.active || p.is_vertex;
    std::vector<Tet4> tets;
    for (const TraceTriangle& t : tr_.triangles)
      tets.push_back({make_label(LabelKind::kCentre, 0, split ? t.side : LabelSide::kNone), t.v[0], t.v[1], t.v[2]});
    if (!holds(tets)) return std::nullopt;
    return tets;
  }

  const TetConfig& c_;
  CutTrace tr_;
  bool bends_;
  std::vector<LabelPositions> where_;
  std::optional<LabelPositions> reference_;
};

}  // namespace

SplitRecipe generate_lut_split(const TetConfig& config) { return LutSplitter(config).run(); }

}  // namespace mtcut::cut
