#include "cut/mt/mt_cut.h"

#include <algorithm>
#include <cassert>
#include <iterator>
#include <chrono>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>

#include "cut/tet_splitter.h"
#include "engine/tet_geometry.h"

namespace mtcut::cut {
namespace {

using Clock = std::chrono::steady_clock;
using engine::FaceMask;
using engine::kTetFaces;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

int local_index(const Tet& tet, std::int32_t v) {
  for (int i = 0; i < 4; ++i)
    if (tet[i].value == v) return i;
  return -1;
}

// The faces of `tet` (bit i: the face opposite local vertex i) a point lies on.
std::uint8_t faces_holding(const Tet& tet, const PointKey& key) {
  const auto without = [&](std::int32_t v) {
    const int i = local_index(tet, v);
    return static_cast<std::uint8_t>(i < 0 ? 0 : 1u << i);
  };
  switch (key.kind) {
    case PointKind::kOriginal:
    case PointKind::kVertexCopy: return static_cast<std::uint8_t>(0xF & ~without(key.ids[0]));
    case PointKind::kEdgePoint: return static_cast<std::uint8_t>(0xF & ~without(key.ids[0]) & ~without(key.ids[1]));
    case PointKind::kFacePoint:
    case PointKind::kFaceNode: {
      std::uint8_t on = 0xF;
      for (int j = 0; j < 3; ++j) on = static_cast<std::uint8_t>(on & ~without(key.ids[j]));
      return on;  // the one vertex not in the face
    }
    case PointKind::kCentre: return 0;
  }
  return 0;
}

std::array<VertId, 3> sorted_face(const Tet& tet, int f) {
  VertId a = tet[kTetFaces[f][0]], b = tet[kTetFaces[f][1]], c = tet[kTetFaces[f][2]];
  // Three compare-exchanges (std::sort's introsort costs several times that on 3).
  if (b < a) std::swap(a, b);
  if (c < b) std::swap(b, c);
  if (b < a) std::swap(a, b);
  return {a, b, c};
}

// The side a tet that is not cut lies on: the side of its strict vertices,
// or, when none is strict, the side its vertices lean to.
VertexState side_of_uncut(const Tet& tet, const CutClassifier& cls) {
  for (VertId v : tet) {
    const VertexState s = cls.state(v);
    if (is_strict(s)) return s;
  }
  double lean = 0;
  for (VertId v : tet) lean += cls.polygon().signed_distance(cls.positions()[v.index()]);
  return lean < 0 ? VertexState::kNeg : VertexState::kPos;
}

PointKey copy_key(VertId v) {
  PointKey key;
  key.kind = PointKind::kVertexCopy;
  key.side = -1;
  key.ids[0] = v.value;
  return key;
}

PointSource copy_source(VertId v, std::span<const Vec3> geometry) {
  PointSource source;
  source.position = geometry[v.index()];
  source.parents[0] = v;
  source.weights[0] = 1;
  return source;
}

bool key_less(const PointKey& a, const PointKey& b) {
  return std::tie(a.kind, a.side, a.ids) < std::tie(b.kind, b.side, b.ids);
}

}  // namespace

MtCut::MtCut(const Mt& mt, const TetBvh& bvh, const CutPolygon& polygon, std::vector<Vec3> geometry,
             const MtCutDef& def, SplitTable& table)
    : polygon_(polygon),
      geometry_(geometry.empty() ? std::vector<Vec3>(mt.positions().begin(), mt.positions().end())
                                 : std::move(geometry)),
      def_(def),
      classifier_(polygon_, geometry_, ClassifierDef{def.snap}) {
  const auto start = Clock::now();
  if (geometry_.size() != mt.num_vertices())
    throw std::invalid_argument("MtCut: the geometry has " + std::to_string(geometry_.size()) + " positions for " +
                                std::to_string(mt.num_vertices()) + " MT vertices");
  // The query box in rest space: the polygon's box, grown by the snap reach
  // (no edge is longer than the model's box) and by the largest displacement.
  engine::Aabb model;
  double displacement = 0;
  for (std::size_t v = 0; v < geometry_.size(); ++v) {
    model.extend(geometry_[v]);
    displacement = std::max(displacement, (geometry_[v] - mt.positions()[v]).lpNorm<Eigen::Infinity>());
  }
  const double margin = std::max(def.snap, ClassifierDef::kMinSnap) * (model.hi - model.lo).norm() + displacement;
  engine::Aabb box;
  box.lo = polygon_.box_min() - Vec3::Constant(margin);
  box.hi = polygon_.box_max() + Vec3::Constant(margin);

  std::vector<TetId> found;
  bvh.for_each_overlapping(mt, box, [&](TetId t) {
    found.push_back(t);
    return true;
  });
  std::sort(found.begin(), found.end());  // BVH order must not leak into the result
  std::vector<std::uint8_t> candidate(found.size(), 0);
  for (std::size_t i = 0; i < found.size(); ++i) candidate[i] = classifier_.add_candidate(mt.tet(found[i]));
  classifier_.finalize();
  // A vertex the cut passes through may lie off the polygon's box (up to the
  // classifier's margin); every tet holding it must move onto its copy, so
  // add the tets around each such vertex (they are not candidates: one that
  // the cut crosses overlaps the polygon's box and was found already).
  {
    std::vector<TetId> around;
    for (VertId v : classifier_.on_vertices()) {
      if (classifier_.state(v) != VertexState::kOnActive) continue;
      engine::Aabb at;
      at.extend(mt.position(v));
      bvh.for_each_overlapping(mt, at, [&](TetId t) {
        const Tet& tet = mt.tet(t);
        if (std::find(tet.begin(), tet.end(), v) != tet.end()) around.push_back(t);
        return true;
      });
    }
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    std::vector<TetId> extra;
    std::set_difference(around.begin(), around.end(), found.begin(), found.end(), std::back_inserter(extra));
    found.insert(found.end(), extra.begin(), extra.end());
    candidate.resize(found.size(), 0);
  }

  for (std::size_t i = 0; i < found.size(); ++i) {
    const Tet& tet = mt.tet(found[i]);
    bool split = false;
    if (candidate[i]) split = classifier_.configure(tet).is_cut();
    if (!split) {
      const bool on_split_vertex = std::any_of(
          tet.begin(), tet.end(), [&](VertId v) { return classifier_.state(v) == VertexState::kOnActive; });
      if (!on_split_vertex || side_of_uncut(tet, classifier_) == VertexState::kPos) continue;
    }
    pending_of_.emplace(found[i].value, static_cast<std::int32_t>(pending_.size()));
    pending_.push_back({found[i], split, false, {}});
  }

  // Every split, and the points the cut makes, in key order.
  if (table.scheme() != def_.scheme) throw std::invalid_argument("MtCut: the split table is for another scheme");
  std::unordered_map<PointKey, PointSource, PointKeyHash> points;
  for (Pending& p : pending_) {
    const Tet& tet = mt.tet(p.tet);
    if (p.split) {
      std::optional<KeyedSplit> keyed = split_tet_keyed(tet, classifier_, table);
      if (!keyed) throw std::logic_error("MtCut: a tet found cut has no split");
      p.keyed = std::move(*keyed);
      for (std::size_t k = 0; k < p.keyed.points.size(); ++k) {
        const PointKey& key = p.keyed.points[k];
        if (key.kind == PointKind::kVertexCopy && key.side > 0) continue;  // the vertex itself
        points.emplace(key, p.keyed.sources[k]);
      }
    } else {
      for (VertId v : tet)
        if (classifier_.state(v) == VertexState::kOnActive) points.emplace(copy_key(v), copy_source(v, geometry_));
    }
  }
  points_.assign(points.begin(), points.end());
  std::sort(points_.begin(), points_.end(), [](const auto& a, const auto& b) { return key_less(a.first, b.first); });

  // Jobs: the fragments creating the pending tets.
  for (const Pending& p : pending_) jobs_.push_back(mt.birth(p.tet));
  std::sort(jobs_.begin(), jobs_.end());
  jobs_.erase(std::unique(jobs_.begin(), jobs_.end()), jobs_.end());
  job_tets_.resize(jobs_.size());
  job_done_.assign(jobs_.size(), 0);
  for (std::size_t i = 0; i < pending_.size(); ++i)
    job_tets_[job_of(mt.birth(pending_[i].tet))].push_back(static_cast<std::int32_t>(i));
  find_seconds_ = seconds_since(start);
}

std::size_t MtCut::job_of(FragId f) const {
  const auto it = std::lower_bound(jobs_.begin(), jobs_.end(), f);
  assert(it != jobs_.end() && *it == f);
  return static_cast<std::size_t>(it - jobs_.begin());
}

std::size_t MtCut::job_cost(const Mt& mt, std::size_t job) const {
  if (job_done_[job]) return 0;
  std::size_t cost = 1;
  for (std::int32_t i : job_tets_[job]) cost += !pending_[static_cast<std::size_t>(i)].done;
  for (TetId t : mt.replaced(jobs_[job])) {
    const auto it = pending_of_.find(t.value);
    if (it != pending_of_.end() && !pending_[static_cast<std::size_t>(it->second)].done) ++cost;
  }
  return cost;
}

void MtCut::add_vertices(Mt& mt, MtChangeReport& report) {
  point_ids_.reserve(points_.size());
  for (const auto& [key, source] : points_) {
    Vec3 rest = Vec3::Zero();
    for (int i = 0; i < 4; ++i)
      if (source.parents[i].valid()) rest += source.weights[i] * mt.position(source.parents[i]);
    const VertId id = mt.add_vertex(rest);
    point_ids_.emplace(key, id);
    report.made_vertices.push_back({id, key, source, rest});
  }
  report.counts.new_vertices += points_.size();
  vertices_added_ = true;
}

VertId MtCut::vertex_of(const PointKey& key) const {
  if (key.kind == PointKind::kOriginal || (key.kind == PointKind::kVertexCopy && key.side > 0)) return VertId(key.ids[0]);
  const auto it = point_ids_.find(key);
  if (it == point_ids_.end()) throw std::logic_error("MtCut: a point was not made");
  return it->second;
}

void MtCut::change_tet(Mt& mt, TetBvh& bvh, Pending& p, MtChangeReport& report) {
  assert(!p.done && mt.alive(p.tet));
  const TetId old = p.tet;
  const Tet tet = mt.tet(old);
  const FragId birth = mt.birth(old), death = mt.death(old);
  const FaceMask mask = mt.boundary_mask(old);
  pieces_.clear();

  if (p.split) {
    const KeyedSplit* split = &p.keyed;
    // Resolve keys to vertices; note the faces of `tet` each corner lies on.
    std::vector<Tet>& made = made_;
    std::vector<std::array<std::uint8_t, 4>>& on_face = on_face_;
    made.resize(split->tets.size());
    on_face.resize(split->tets.size());
    for (std::size_t j = 0; j < split->tets.size(); ++j)
      for (int c = 0; c < 4; ++c) {
        const PointKey& key = split->tets[j][c];
        on_face[j][c] = faces_holding(tet, key);
        made[j][c] = vertex_of(key);
      }
    // Surface faces: a piece face inside a face of `tet` keeps that face's
    // bit; a face no other piece shares and inside no face of `tet` is made
    // by the cut.
    std::vector<std::array<VertId, 3>>& faces = faces_;
    faces.clear();
    for (const Tet& m : made)
      for (int f = 0; f < 4; ++f) faces.push_back(sorted_face(m, f));
    std::sort(faces.begin(), faces.end());
    for (std::size_t j = 0; j < made.size(); ++j) {
      FaceMask piece_mask = 0;
      for (int f = 0; f < 4; ++f) {
        const auto& fv = kTetFaces[f];
        const std::uint8_t common = on_face[j][fv[0]] & on_face[j][fv[1]] & on_face[j][fv[2]];
        bool surface;
        if (common != 0) {
          surface = (common & mask) != 0;
        } else {
          const auto face = sorted_face(made[j], f);
          const auto range = std::equal_range(faces.begin(), faces.end(), face);
          surface = range.second - range.first == 1;
        }
        if (surface) piece_mask = static_cast<FaceMask>(piece_mask | 1u << f);
      }
      pieces_.push_back(mt.add_tet(made[j], birth, death, piece_mask));
    }
    ++report.counts.split_tets;
    report.counts.new_tets += made.size();
  } else {
    // Relabel onto the negative copies of the vertices the cut passes
    // through; a face lying in the cut (all its vertices on it) is now surface.
    Tet moved = tet;
    for (VertId& v : moved) {
      if (classifier_.state(v) == VertexState::kOnActive) v = vertex_of(copy_key(v));
    }
    FaceMask piece_mask = mask;
    for (int f = 0; f < 4; ++f) {
      const auto& fv = kTetFaces[f];
      if (std::all_of(fv.begin(), fv.end(), [&](int c) { return is_on(classifier_.state(tet[c])); }))
        piece_mask = static_cast<FaceMask>(piece_mask | 1u << f);
    }
    pieces_.push_back(mt.add_tet(moved, birth, death, piece_mask));
    ++report.counts.relabeled_tets;
  }
  mt.kill_tet(old);
  bvh.replace(mt, old, pieces_);
  report.replaced.push_back({old, static_cast<std::uint32_t>(report.made_tets.size()),
                             static_cast<std::uint32_t>(pieces_.size())});
  report.made_tets.insert(report.made_tets.end(), pieces_.begin(), pieces_.end());
  p.done = true;
}

void MtCut::process(Mt& mt, TetBvh& bvh, std::size_t job, MtChangeReport& report) {
  if (job_done_[job]) throw std::logic_error("MtCut::process: job already done");
  const FragId f = jobs_[job];
  const auto start = Clock::now();
  if (!vertices_added_) add_vertices(mt, report);
  // Step 2 for the tets f creates and, so that f sees its whole region
  // final, the pending tets it replaces (their own job will find them done).
  for (std::int32_t i : job_tets_[job]) {
    Pending& p = pending_[static_cast<std::size_t>(i)];
    if (!p.done) change_tet(mt, bvh, p, report);
  }
  std::vector<std::int32_t> from_parents;
  for (TetId t : mt.replaced(f)) {
    const auto it = pending_of_.find(t.value);
    if (it != pending_of_.end() && !pending_[static_cast<std::size_t>(it->second)].done)
      from_parents.push_back(it->second);
  }
  for (std::int32_t i : from_parents) change_tet(mt, bvh, pending_[static_cast<std::size_t>(i)], report);
  const auto dag_start = Clock::now();
  report.counts.split_seconds += std::chrono::duration<double>(dag_start - start).count();

  // Step 3: UpdateProcessFragment.
  if (f != mt.root() && f != mt.drain()) {
    Decomposition d = decompose_fragment(mt, f, scratch_);
    if (d.outcome == DecomposeOutcome::kSplit) {
      ++report.counts.split_fragments;
      report.counts.new_fragments += d.parts.size() - 1;
      report.fragment_splits.push_back({f, std::move(d.parts)});
    } else if (d.outcome == DecomposeOutcome::kKeptWhole) {
      ++report.counts.whole_fragments;
    }
  }
  report.counts.dag_seconds += seconds_since(dag_start);
  ++report.counts.jobs;
  report.processed.push_back(f);
  job_done_[job] = 1;
  ++jobs_done_;
}

engine::ValidationReport MtCut::validate(const Mt& mt) const {
  engine::ValidationReport report;
  std::size_t done = 0;
  for (std::size_t j = 0; j < jobs_.size(); ++j) {
    done += job_done_[j];
    for (std::int32_t i : job_tets_[j]) {
      const Pending& p = pending_[static_cast<std::size_t>(i)];
      if (p.done && mt.alive(p.tet)) report.add("MtCut: tet " + std::to_string(p.tet.value) + " changed but alive");
      if (!p.done && !mt.alive(p.tet)) report.add("MtCut: tet " + std::to_string(p.tet.value) + " pending but dead");
      if (!p.done && mt.birth(p.tet) != jobs_[j])
        report.add("MtCut: pending tet " + std::to_string(p.tet.value) + " left its job's fragment");
      if (job_done_[j] && !p.done) report.add("MtCut: job " + std::to_string(j) + " done with a pending tet");
    }
  }
  if (done != jobs_done_) report.add("MtCut: jobs done miscounted");
  if (pending_of_.size() != pending_.size()) report.add("MtCut: a tet is pending twice");
  return report;
}

MtChangeReport cut_mt(Mt& mt, TetBvh& bvh, const CutPolygon& polygon, std::vector<Vec3> geometry,
                      const CutMtOptions& options, SplitTable* table) {
  SplitTable local(options.def.scheme);
  SplitTable& recipes = table ? *table : local;
  bvh.refresh(mt);  // before the search; the cut's own edits never rebuild it
  MtCut cut(mt, bvh, polygon, std::move(geometry), options.def, recipes);
  std::vector<std::size_t> order(cut.jobs().size());
  std::iota(order.begin(), order.end(), 0);
  if (options.order == JobOrder::kDescending) std::reverse(order.begin(), order.end());
  if (options.order == JobOrder::kShuffled) std::shuffle(order.begin(), order.end(), std::mt19937_64(options.seed));
  MtChangeReport report;
  report.counts.find_seconds = cut.find_seconds();
  for (std::size_t job : order) cut.process(mt, bvh, job, report);
  return report;
}

}  // namespace mtcut::cut
