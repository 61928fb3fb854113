#include "engine/mt/collapse.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <utility>

#include "absl/container/flat_hash_map.h"
#include "engine/mt/tet_error.h"
#include "engine/mt/triangle_index.h"
#include "engine/tet_adjacency.h"
#include "engine/tet_geometry.h"

namespace mtcut::engine {
namespace {

constexpr double kJung = 0.6124;  // just above sqrt(3/8) = 0.612372...
constexpr std::int32_t kOmega = std::numeric_limits<std::int32_t>::max();  // the dummy vertex closing the surface

int local_index(const Tet& t, VertId v) {
  for (int k = 0; k < 4; ++k)
    if (t[k] == v) return k;
  return -1;
}

std::uint64_t edge_key(std::int32_t a, std::int32_t b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

std::array<std::int32_t, 3> tri_key(std::int32_t a, std::int32_t b, std::int32_t c) {
  std::array<std::int32_t, 3> k = {a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

template <class T>
void sort_unique(std::vector<T>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

using FaceKey = std::array<std::int32_t, 3>;

FaceKey face_key(const std::array<VertId, 3>& face) { return tri_key(face[0].value, face[1].value, face[2].value); }

// The nearest of `faces` to p and its distance, or the first within `enough`.
std::pair<std::size_t, double> nearest_face(const Mt& mt, const Vec3& p, std::span<const std::array<VertId, 3>> faces,
                                            double enough = -1.0) {
  std::pair<std::size_t, double> nearest{0, std::numeric_limits<double>::infinity()};
  for (std::size_t k = 0; k < faces.size() && nearest.second > enough; ++k) {
    const auto& f = faces[k];
    const double d = point_triangle_distance(p, mt.position(f[0]), mt.position(f[1]), mt.position(f[2]));
    if (d < nearest.second) nearest = {k, d};
  }
  return nearest;
}

}  // namespace

struct SimplificationMesh::FineSurface {
  TriangleIndex index;
  std::vector<Vec3> samples;
  absl::flat_hash_map<FaceKey, std::vector<std::int32_t>> held;  // current surface face -> its samples
};

SimplificationMesh::SimplificationMesh(Mt& mt, const CollapseOptions& options)
    : mt_(mt), options_(options), star_(mt.num_vertices()), on_boundary_(mt.num_vertices(), 0),
      mark_(mt.num_vertices(), 0) {
  std::vector<std::array<VertId, 3>> surface;
  for (std::size_t i = 0; i < mt.num_tets(); ++i) {
    const TetId t(i);
    if (!mt.alive(t) || mt.death(t).valid()) continue;
    ++live_tets_;
    const Tet& v = mt.tet(t);
    for (VertId a : v) star_[a.index()].push_back(t);
    for (int f = 0; f < 4; ++f)
      if (mt.boundary_mask(t) & (1u << f)) {
        surface.push_back(face_vertices(v, f));
        for (VertId a : surface.back()) on_boundary_[a.index()] = 1;
      }
  }
  if (options_.preserve_boundary) return;
  // The fine surface's samples: each vertex, edge midpoint and centroid,
  // held by the first face that has it.
  std::vector<Triangle> triangles;
  triangles.reserve(surface.size());
  for (const auto& f : surface) triangles.push_back({mt.position(f[0]), mt.position(f[1]), mt.position(f[2])});
  fine_ = std::make_unique<FineSurface>(FineSurface{TriangleIndex(std::move(triangles)), {}, {}});
  std::vector<char> vertex_taken(mt.num_vertices(), 0);
  absl::flat_hash_map<std::uint64_t, char> edge_taken;
  for (const auto& f : surface) {
    std::vector<std::int32_t>& held = fine_->held[face_key(f)];
    const auto add = [&](const Vec3& p) {
      held.push_back(static_cast<std::int32_t>(fine_->samples.size()));
      fine_->samples.push_back(p);
    };
    const Vec3 &a = mt.position(f[0]), &b = mt.position(f[1]), &c = mt.position(f[2]);
    for (int k = 0; k < 3; ++k) {
      if (!std::exchange(vertex_taken[f[k].index()], 1)) add(mt.position(f[k]));
      if (!std::exchange(edge_taken[edge_key(f[k].value, f[(k + 1) % 3].value)], 1))
        add(0.5 * (mt.position(f[k]) + mt.position(f[(k + 1) % 3])));
    }
    add((a + b + c) / 3.0);
  }
}

SimplificationMesh::~SimplificationMesh() = default;

void SimplificationMesh::ring(VertId v, std::vector<VertId>& out) const {
  out.clear();
  ++stamp_;
  for (TetId t : star(v))
    for (VertId a : mt_.tet(t))
      if (a != v && mark_[a.index()] != stamp_) {
        mark_[a.index()] = stamp_;
        out.push_back(a);
      }
}

void SimplificationMesh::describe_star(VertId v, StarInfo& info) {
  info.surface.clear();
  info.num_planes = 0;
  info.corner = false;
  info.worst_quality = -1.0;  // not computed yet: only needed when a new tet is poor
  for (TetId t : star(v)) {
    const FaceMask mask = mt_.boundary_mask(t);
    const int iv = local_index(mt_.tet(t), v);
    for (int f = 0; f < 4; ++f)
      if (f != iv && (mask & (1u << f))) info.surface.push_back(face_vertices(mt_.tet(t), f));
  }
  for (const auto& face : info.surface) {
    const Vec3 &a = mt_.position(face[0]), &b = mt_.position(face[1]), &c = mt_.position(face[2]);
    bool found = false;
    for (int p = 0; p < info.num_planes && !found; ++p) {
      const auto& q = info.planes[p];
      found = orient3d_sign(q[0], q[1], q[2], a) == 0 && orient3d_sign(q[0], q[1], q[2], b) == 0 &&
              orient3d_sign(q[0], q[1], q[2], c) == 0;
    }
    if (found) continue;
    if (info.num_planes == 2) {
      info.corner = true;
      break;
    }
    info.planes[info.num_planes++] = {a, b, c};
  }
}

double SimplificationMesh::worst_quality(VertId v, StarInfo& info) const {
  if (info.worst_quality < 0.0) {
    info.worst_quality = 1.0;
    for (TetId t : star(v)) {
      const auto c = mt_.corners(t);
      info.worst_quality = std::min(info.worst_quality, tet_quality(c[0], c[1], c[2], c[3]));
    }
  }
  return info.worst_quality;
}

float SimplificationMesh::cost_of(VertId v, VertId w, StarInfo& info, float bound) {
  constexpr float kInvalid = std::numeric_limits<float>::infinity();
  const bool surface_move = !info.surface.empty();
  if (surface_move) {
    // A surface vertex may only move to a surface vertex (the link condition
    // would refuse the rest too; this is the cheap early answer).
    if (!on_boundary(w)) return kInvalid;
    if (options_.preserve_boundary) {
      if (info.corner) return kInvalid;
      const Vec3& pw = mt_.position(w);
      for (int p = 0; p < info.num_planes; ++p)
        if (orient3d_sign(info.planes[p][0], info.planes[p][1], info.planes[p][2], pw) != 0) {
          ++rejections_.boundary;
          return kInvalid;
        }
    }
  }
  // Pass 1: the new tets, their validity and longest edges.
  made_.clear();
  double longest_max = 0.0;
  for (TetId t : star(v)) {
    Tet verts = mt_.tet(t);
    const int iw = local_index(verts, w);
    if (iw >= 0) {
      // Dropped. Its face away from w must not be surface, or the tets
      // around w would change their surface faces (the object would lose
      // the tet's slab of volume in a way no fragment records).
      if (mt_.boundary_mask(t) & (1u << iw)) {
        ++rejections_.boundary;
        return kInvalid;
      }
      continue;
    }
    verts[local_index(verts, v)] = w;
    const Vec3 &a = mt_.position(verts[0]), &b = mt_.position(verts[1]), &c = mt_.position(verts[2]),
               &d = mt_.position(verts[3]);
    if (orient3d_sign(a, b, c, d) <= 0) {
      ++rejections_.inversion;
      return kInvalid;
    }
    const double longest2 = std::max({(a - b).squaredNorm(), (a - c).squaredNorm(), (a - d).squaredNorm(),
                                      (b - c).squaredNorm(), (b - d).squaredNorm(), (c - d).squaredNorm()});
    const double longest = std::sqrt(longest2);
    // tet_quality, sharing the longest edge.
    const double quality = std::numbers::sqrt2 * (b - a).cross(c - a).dot(d - a) / (longest2 * longest);
    if (quality < options_.min_quality && quality < worst_quality(v, info)) {
      ++rejections_.quality;
      return kInvalid;
    }
    if (0.5 * longest >= static_cast<double>(bound)) return kInvalid;  // R >= L / 2: too dear already
    longest_max = std::max(longest_max, longest);
    made_.push_back({verts, longest});
  }
  if (made_.empty()) return kInvalid;
  // Pass 2: the cost, max R. R >= L / 2 and (Jung) R <= sqrt(3/8) L, so a tet
  // whose sqrt(3/8) L is below half the longest edge of all cannot hold the
  // max: only the few longest tets need R.
  float cost = 0.0f;
  for (const MadeTet& m : made_) {
    if (kJung * m.longest <= 0.5 * longest_max) continue;
    const Vec3 &a = mt_.position(m.verts[0]), &b = mt_.position(m.verts[1]), &c = mt_.position(m.verts[2]),
               &d = mt_.position(m.verts[3]);
    cost = std::max(cost, tet_error(a, b, c, d));
    if (cost >= bound) return kInvalid;  // not better than a collapse already found
  }
  if (surface_move && fine_) {
    const double limit = std::min(static_cast<double>(cost), options_.max_surface_deviation);
    if (!(surface_moved_by(v, w, info, limit) <= limit)) {
      ++rejections_.boundary;
      return kInvalid;
    }
  }
  return cost;
}

void SimplificationMesh::moved_faces(VertId v, VertId w, const StarInfo& info,
                                     std::vector<std::array<VertId, 3>>& out) const {
  out.clear();
  for (const auto& face : info.surface) {
    if (face[0] == w || face[1] == w || face[2] == w) continue;
    out.push_back(face);
    for (VertId& a : out.back())
      if (a == v) a = w;
  }
}

double SimplificationMesh::surface_moved_by(VertId v, VertId w, const StarInfo& info, double limit) {
  moved_faces(v, w, info, moved_);
  if (moved_.empty()) return std::numeric_limits<double>::infinity();
  double worst = 0.0;
  for (const auto& f : moved_) {
    const Vec3 &a = mt_.position(f[0]), &b = mt_.position(f[1]), &c = mt_.position(f[2]);
    for (const Vec3& p : {Vec3(0.5 * (a + b)), Vec3(0.5 * (b + c)), Vec3(0.5 * (c + a)), Vec3((a + b + c) / 3.0)}) {
      worst = std::max(worst, fine_->index.distance(p, std::nextafter(limit, HUGE_VAL), worst));
      if (worst > limit) return worst;
    }
  }
  for (const auto& face : info.surface) {
    const auto it = fine_->held.find(face_key(face));
    if (it == fine_->held.end()) continue;
    for (std::int32_t sample : it->second) {
      worst = std::max(worst, nearest_face(mt_, fine_->samples[static_cast<std::size_t>(sample)], moved_, worst).second);
      if (worst > limit) return worst;
    }
  }
  return worst;
}

bool SimplificationMesh::link_condition(VertId v, VertId w) {
  // Lk(v) n Lk(w) must equal Lk(vw), the surface closed by the dummy vertex
  // kOmega (each surface face (x, p, q) becomes a tet (x, p, q, omega)).
  // v's side as marks (vertices) and sorted lists (edges, triangles); w's
  // side is walked and looked up.
  ++stamp_;
  auto& edges_v = link_e_[0];
  auto& tris_v = link_t_[0];
  edges_v.clear(), tris_v.clear(), link_vw_.clear(), link_ew_.clear();
  bool v_surface = false;
  for (TetId t : star(v)) {
    const Tet& tv = mt_.tet(t);
    const int iv = local_index(tv, v);
    const auto opp = face_vertices(tv, iv);
    const std::int32_t a = opp[0].value, b = opp[1].value, c = opp[2].value;
    for (VertId q : opp) mark_[q.index()] = stamp_;
    edges_v.insert(edges_v.end(), {edge_key(a, b), edge_key(b, c), edge_key(c, a)});
    tris_v.push_back(tri_key(a, b, c));
    if (local_index(tv, w) >= 0) {
      std::int32_t e[2], n = 0;
      for (std::int32_t q : {a, b, c})
        if (q != w.value) e[n++] = q;
      link_vw_.insert(link_vw_.end(), {e[0], e[1]});
      link_ew_.push_back(edge_key(e[0], e[1]));
    }
    const FaceMask mask = mt_.boundary_mask(t);
    for (int f = 0; f < 4; ++f) {
      if (f == iv || !(mask & (1u << f))) continue;
      v_surface = true;
      std::int32_t pq[2], n = 0;
      for (VertId u : face_vertices(tv, f))
        if (u != v) pq[n++] = u.value;
      edges_v.insert(edges_v.end(), {edge_key(pq[0], kOmega), edge_key(pq[1], kOmega)});
      tris_v.push_back(tri_key(pq[0], pq[1], kOmega));
      if (pq[0] == w.value || pq[1] == w.value) {
        const std::int32_t other = pq[0] == w.value ? pq[1] : pq[0];
        link_vw_.insert(link_vw_.end(), {other, kOmega});
        link_ew_.push_back(edge_key(other, kOmega));
      }
    }
  }
  sort_unique(edges_v), sort_unique(tris_v);
  const auto in_ring_v = [&](std::int32_t q) { return q != kOmega && mark_[static_cast<std::size_t>(q)] == stamp_; };
  const auto in_vw = [&](std::int32_t q) { return std::find(link_vw_.begin(), link_vw_.end(), q) != link_vw_.end(); };
  const auto edge_ok = [&](std::int32_t p, std::int32_t q) {
    // An edge of Lk(w) that is also in Lk(v) must be in Lk(vw).
    if (!(in_ring_v(p) || p == kOmega) || !(in_ring_v(q) || q == kOmega)) return true;
    const std::uint64_t key = edge_key(p, q);
    if (!std::binary_search(edges_v.begin(), edges_v.end(), key)) return true;
    return std::find(link_ew_.begin(), link_ew_.end(), key) != link_ew_.end();
  };
  bool w_surface = false;
  for (TetId t : star(w)) {
    const Tet& tw = mt_.tet(t);
    const int iw = local_index(tw, w);
    const auto opp = face_vertices(tw, iw);
    const std::int32_t a = opp[0].value, b = opp[1].value, c = opp[2].value;
    if (std::binary_search(tris_v.begin(), tris_v.end(), tri_key(a, b, c))) return false;
    for (std::int32_t q : {a, b, c})
      if (in_ring_v(q) && !in_vw(q)) return false;
    if (!edge_ok(a, b) || !edge_ok(b, c) || !edge_ok(c, a)) return false;
    const FaceMask mask = mt_.boundary_mask(t);
    for (int f = 0; f < 4; ++f) {
      if (f == iw || !(mask & (1u << f))) continue;
      w_surface = true;
      std::int32_t pq[2], n = 0;
      for (VertId u : face_vertices(tw, f))
        if (u != w) pq[n++] = u.value;
      if (std::binary_search(tris_v.begin(), tris_v.end(), tri_key(pq[0], pq[1], kOmega))) return false;
      if (!edge_ok(pq[0], kOmega) || !edge_ok(pq[1], kOmega)) return false;
    }
  }
  // The dummy itself is a common vertex when both are on the surface.
  return !(v_surface && w_surface) || in_vw(kOmega);
}

CollapseChoice SimplificationMesh::best_collapse(VertId v, bool check_link) {
  if (star(v).empty()) return {};
  describe_star(v, info_);
  if (options_.preserve_boundary && info_.corner) return {};
  ring(v, candidates_);
  // Nearest targets first: they tend to be the cheapest, which tightens the
  // bound that cuts the evaluation of the others short.
  const Vec3& pv = mt_.position(v);
  std::sort(candidates_.begin(), candidates_.end(), [&](VertId a, VertId b) {
    const double da = (mt_.position(a) - pv).squaredNorm(), db = (mt_.position(b) - pv).squaredNorm();
    return da < db || (da == db && a < b);
  });
  excluded_.clear();
  // The cheapest target that passes the link condition; a failing one is
  // excluded and the search repeated (rare: a few times at most).
  for (int attempt = 0; attempt < 4; ++attempt) {
    CollapseChoice best;
    for (VertId w : candidates_) {
      if (std::find(excluded_.begin(), excluded_.end(), w) != excluded_.end()) continue;
      const float cost = cost_of(v, w, info_, best.cost);
      if (cost < best.cost) best = {w, cost};
    }
    if (!best.valid()) return {};
    if (!check_link || link_condition(v, best.target)) return best;
    ++rejections_.link;
    excluded_.push_back(best.target);
  }
  return {};
}

CollapseChoice SimplificationMesh::check_collapse(VertId v, VertId target) {
  if (star(v).empty() || star(target).empty()) return {};
  describe_star(v, info_);
  ring(v, ring_);
  if (std::find(ring_.begin(), ring_.end(), target) == ring_.end()) return {};
  const float cost = cost_of(v, target, info_, std::numeric_limits<float>::infinity());
  if (!std::isfinite(cost)) return {};
  if (!link_condition(v, target)) {
    ++rejections_.link;
    return {};
  }
  return {target, cost};
}

FragId SimplificationMesh::apply(VertId v, VertId w, FragId into) {
  // The fine surface's samples that the faces around v hold go to the
  // nearest of the faces the collapse makes.
  if (fine_ && on_boundary(v)) {
    describe_star(v, info_);
    moved_faces(v, w, info_, moved_);
    loose_.clear();
    for (const auto& face : info_.surface)
      if (const auto it = fine_->held.find(face_key(face)); it != fine_->held.end()) {
        loose_.insert(loose_.end(), it->second.begin(), it->second.end());
        fine_->held.erase(it);
      }
    assert((loose_.empty() || !moved_.empty()) && "a surface collapse makes no surface face");
    for (std::int32_t sample : loose_) {
      const std::size_t nearest = nearest_face(mt_, fine_->samples[static_cast<std::size_t>(sample)], moved_).first;
      fine_->held[face_key(moved_[nearest])].push_back(sample);
    }
  }

  const FragId fragment = into.valid() ? into : mt_.add_fragment();
  old_star_.assign(star(v).begin(), star(v).end());
  for (TetId t : old_star_)
    for (VertId a : mt_.tet(t)) {
      if (a == v) continue;
      auto& list = star_[a.index()];
      const auto it = std::find(list.begin(), list.end(), t);
      assert(it != list.end());
      *it = list.back();
      list.pop_back();
    }
  star_[v.index()].clear();
  live_tets_ -= old_star_.size();

  new_tets_.clear();
  for (TetId t : old_star_) {
    const Tet verts_before = mt_.tet(t);
    const FaceMask mask_before = mt_.boundary_mask(t);
    if (mt_.birth(t) == fragment) {
      mt_.kill_tet(t);
    } else {
      mt_.set_death(t, fragment);
    }
    Tet verts = verts_before;
    if (local_index(verts, w) >= 0) continue;
    const int iv = local_index(verts, v);
    verts[iv] = w;
    // The face away from w keeps its neighbour and so its surface bit; the
    // others are decided below, once the new star of w is known.
    const auto keep = static_cast<FaceMask>(mask_before & (1u << iv));
    new_tets_.push_back(mt_.add_tet(verts, fragment, FragId(), keep));
  }
  for (TetId t : new_tets_)
    for (VertId a : mt_.tet(t)) star_[a.index()].push_back(t);
  live_tets_ += new_tets_.size();

  for (TetId t : new_tets_) {
    const Tet& verts = mt_.tet(t);
    const int iw = local_index(verts, w);
    FaceMask mask = mt_.boundary_mask(t);
    for (int f = 0; f < 4; ++f) {
      if (f == iw) continue;
      const auto face = face_vertices(verts, f);
      int holders = 0;
      for (TetId u : star(w)) {
        const Tet& uv = mt_.tet(u);
        holders += local_index(uv, face[0]) >= 0 && local_index(uv, face[1]) >= 0 && local_index(uv, face[2]) >= 0;
      }
      if (holders == 1) mask |= static_cast<FaceMask>(1u << f);
    }
    mt_.set_boundary_mask(t, mask);
  }
  return fragment;
}

void SimplificationMesh::finish(FragId drain) {
  for (std::size_t i = 0; i < mt_.num_tets(); ++i) {
    const TetId t(i);
    if (mt_.alive(t) && !mt_.death(t).valid()) mt_.set_death(t, drain);
  }
  for (auto& s : star_) std::vector<TetId>().swap(s);
  live_tets_ = 0;
}

}  // namespace mtcut::engine
