#include "cut/mt/mt_cut.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cstdint>
#include <iterator>
#include <chrono>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>

#include "cut/tet_splitter.h"
#include "engine/radix_sort.h"
#include "engine/reserve_geometric.h"
#include "engine/stopwatch.h"
#include "engine/tet_geometry.h"

namespace mtcut::cut {
namespace {

using Clock = std::chrono::steady_clock;
using engine::FaceMask;
using engine::kTetFaces;

PointKey copy_key(VertId v) {
  PointKey key;
  key.kind = PointKind::kVertexCopy;
  key.side = -1;
  key.ids[0] = v.value;
  return key;
}

// Sorts ids and drops repeats in O(n + range / 64): marks them in `bits`
// (all 0 before and after) and reads them back in order. A cut through the
// whole object finds thousands of tets; std::sort's comparisons cost ten
// times as much.
template <class Id>
void sort_unique(std::vector<Id>& ids, std::vector<std::uint64_t>& bits) {
  if (ids.size() < 64) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return;
  }
  std::size_t lo = SIZE_MAX, hi = 0;
  for (Id id : ids) {
    const std::size_t w = id.index() >> 6;
    if (w >= bits.size()) bits.resize(std::max(w + 1, 2 * bits.size()), 0);
    bits[w] |= std::uint64_t{1} << (id.index() & 63);
    lo = std::min(lo, w);
    hi = std::max(hi, w);
  }
  ids.clear();
  for (std::size_t w = lo; w <= hi; ++w) {
    for (std::uint64_t word = bits[w]; word != 0; word &= word - 1)
      ids.push_back(Id(static_cast<std::int32_t>(64 * w + static_cast<std::size_t>(std::countr_zero(word)))));
    bits[w] = 0;
  }
}

// The tet is split by the plane alone: every vertex strictly on a side and
// every edge it straddles crossed inside the polygon. Its split is then the
// same under every polygon of the plane that holds these crossings.
bool crossed_completely(const TetConfig& config) {
  for (VertexState s : config.vertex)
    if (!is_strict(s)) return false;
  for (int k = 0; k < 6; ++k)
    if (config.straddles(k) && !config.edge_active(k)) return false;
  return true;
}

// An edge through which a part's committed crack passes is crossed, for
// every later cut of the part (its outline may have moved off the point).
void cover_committed_edges(const Tet& tet, const PartRecord& record, TetConfig& config) {
  for (int k = 0; k < 6; ++k) {
    if (!config.straddles(k) || config.edge_active(k)) continue;
    if (record.point(point_key(tet, make_label(LabelKind::kEdge, k, LabelSide::kPos))).valid())
      config.covered = static_cast<std::uint8_t>(config.covered | 1u << k);
  }
}

// The order of new vertex ids (number_points_by_key sorts packed keys in it).
[[maybe_unused]] bool key_less(const PointKey& a, const PointKey& b) {
  return std::tie(a.kind, a.side, a.ids) < std::tie(b.kind, b.side, b.ids);
}

}  // namespace

std::vector<std::uint8_t> kept_front_splits(const Mt& mt, const MtChangeReport& front, const CutPolygon& polygon,
                                            const PartRecord& record, double snap, double reach,
                                            CutClassifier::Scratch* scratch) {
  std::vector<std::uint8_t> keep(front.replaced.size(), 0);
  CutClassifier classifier(polygon, mt.positions(), ClassifierDef{snap}, scratch);
  classifier.expect_candidates(front.replaced.size());
  for (const TetReplacement& r : front.replaced) classifier.add_candidate(mt.tet(r.old));
  classifier.finalize();
  for (std::size_t i = 0; i < front.replaced.size(); ++i) {
    const TetReplacement& r = front.replaced[i];
    if (r.config == 0) continue;
    const Tet& tet = mt.tet(r.old);
    if (std::any_of(tet.begin(), tet.end(),
                    [&](VertId v) { return std::abs(polygon.signed_distance(mt.position(v))) <= reach; }))
      continue;
    TetConfig config = classifier.configure(tet);
    cover_committed_edges(tet, record, config);
    keep[i] = config.is_cut() && !crossed_completely(config) && config.key() == r.config;
  }
  return keep;
}

MtCut::MtCut(const Mt& mt, const TetBvh& bvh, const CutPolygon& polygon, std::span<const Vec3> geometry,
             const MtCutDef& def, SplitTable& table, MtCutWorkspace* workspace)
    : polygon_(polygon),
      def_(def),
      own_workspace_(workspace ? nullptr : std::make_unique<MtCutWorkspace>()),
      workspace_(workspace ? workspace : own_workspace_.get()) {
  const auto start = Clock::now();
  const std::span<const Vec3> given = geometry;
  const bool deformed = !geometry.empty();
  if (!deformed) geometry = mt.positions();
  if (geometry.size() != mt.num_vertices())
    throw std::invalid_argument("MtCut: the geometry has " + std::to_string(geometry.size()) + " positions for " +
                                std::to_string(mt.num_vertices()) + " MT vertices");
  // The search's state lives while the cut is searched (the jobs only
  // append what it resolved).
  CutClassifier classifier(polygon_, geometry, ClassifierDef{def.snap}, &workspace_->classifier, def.continuation);
  // The query box in rest space: the polygon's box, grown by the snap reach
  // (no edge is longer than the model's box) and by the largest displacement.
  // On rest geometry the BVH's root box is the model's: no pass over the
  // vertices (a per-frame cut touches a few dozen of thousands).
  engine::Aabb model = bvh.bounds();
  double displacement = 0;
  if (deformed) {
    model = engine::Aabb{};
    for (std::size_t v = 0; v < geometry.size(); ++v) {
      model.extend(geometry[v]);
      displacement = std::max(displacement, (geometry[v] - mt.positions()[v]).lpNorm<Eigen::Infinity>());
    }
  }
  const double margin = std::max(def.snap, ClassifierDef::kMinSnap) * (model.hi - model.lo).norm() + displacement;
  engine::Aabb box;
  box.lo = polygon_.box_min() - Vec3::Constant(margin);
  box.hi = polygon_.box_max() + Vec3::Constant(margin);
  engine::Aabb near_front = box;
  if (def.search) {
    near_front.lo = box.lo.cwiseMax(def.search->lo - Vec3::Constant(margin));
    near_front.hi = box.hi.cwiseMin(def.search->hi + Vec3::Constant(margin));
  }

  // Tets with every vertex strictly on one side are dropped before the sort,
  // and so are the BVH's nodes that lie on one side of the plane (their
  // deformed tets within `displacement` of them): a cut through the whole
  // object walks only the nodes along its plane, not every tet.
  // A part's committed pieces are never cut again (part_record.h).
  const PartRecord* record = def.record;
  std::vector<TetId> found;
  const auto searched = [&](TetId t) { return !(record && record->owns(t)); };
  const auto add = [&](TetId t) {
    if (classifier.may_be_cut(mt.tet(t))) found.push_back(t);
    return true;
  };
  if (def.candidates) {
    for (TetId t : *def.candidates)
      if (mt.alive(t) && searched(t) && engine::tet_box_overlaps(mt, t, def.search ? near_front : box)) add(t);
  } else if (def.search || !def.grown_from) {
    bvh.for_each_overlapping(
        mt, def.search ? near_front : box,
        [&](const engine::Aabb& node) { return polygon_.box_may_touch_plane(node, displacement); }, searched, add);
  }
  if (def.grown_from && !def.candidates) {
    // Where the polygon covers what grown_from did not, within the snap
    // reach: not along the outline the two share.
    engine::Aabb grown = polygon_.box_beyond(*def.grown_from);
    grown.lo = box.lo.cwiseMax(grown.lo - Vec3::Constant(margin));
    grown.hi = box.hi.cwiseMin(grown.hi + Vec3::Constant(margin));
    bvh.for_each_overlapping(
        mt, grown,
        [&](const engine::Aabb& node) {
          return polygon_.box_may_touch_plane(node, displacement) &&
                 !def.grown_from->box_projects_inside(node, margin);
        },
        searched, add);
  }
  sort_unique(found, workspace_->id_bits);  // BVH order must not leak into the result
  classifier.expect_candidates(found.size());
  for (TetId t : found) classifier.add_candidate(mt.tet(t));
  add_tets_around_on_vertices(mt, bvh, classifier, record, found);
  classifier.finalize();

  if (table.scheme() != def_.scheme) throw std::invalid_argument("MtCut: the split table is for another scheme");
  // Which tets change, and their pieces over vertex ids (new points are
  // numbered as this scan first meets them, then renumbered by key).
  first_vertex_ = mt.num_vertices();
  std::vector<TetConfig> configs(found.size());
  std::vector<std::array<std::int32_t, 6>> edge_numbers(found.size());
  std::vector<std::uint8_t> split(found.size(), 0);
  std::vector<std::uint8_t> positive(found.size(), 0);  // not split, on the positive side
  for (std::size_t i = 0; i < found.size(); ++i) {
    const Tet& tet = mt.tet(found[i]);
    configs[i] = classifier.configure(tet, edge_numbers[i]);
    if (record) cover_committed_edges(tet, *record, configs[i]);
    split[i] = configs[i].is_cut();
    positive[i] = !split[i] && classifier.side_of_uncut(tet) == VertexState::kPos;
  }
  // A vertex the cut passes through is split only when it separates
  // something: a tet around it is split or on the positive side (which keeps
  // its id). Else every tet around it would move onto its copy and leave it
  // unused, as when a polygon lies in the object's surface.
  std::vector<std::uint8_t>& separating = workspace_->separating;
  if (separating.size() < mt.num_vertices()) separating.resize(mt.num_vertices(), 0);
  struct Clear {  // hands `separating` back clean, whatever happens (only on-vertices are set)
    std::vector<std::uint8_t>& separating;
    const CutClassifier& classifier;
    ~Clear() {
      for (VertId v : classifier.on_vertices()) separating[v.index()] = 0;
    }
  } clear{separating, classifier};
  for (std::size_t i = 0; i < found.size(); ++i)
    if (split[i] || positive[i])
      for (VertId v : mt.tet(found[i]))
        if (classifier.state(v) == VertexState::kOnActive) separating[v.index()] = 1;
  edge_point_.assign(3 * classifier.edges_numbered(), -1);  // every number configure gave
  for (std::size_t i = 0; i < found.size(); ++i) {
    const Tet& tet = mt.tet(found[i]);
    Pending p;
    p.tet = found[i];
    p.split = split[i] != 0;
    if (!p.split) {
      const bool on_split_vertex =
          std::any_of(tet.begin(), tet.end(), [&](VertId v) { return splits(v); });
      if (!on_split_vertex || positive[i]) continue;
    }
    const bool complete = p.split && crossed_completely(configs[i]);
    crossed_partially_ += p.split && !complete;
    if (def.select != CutSelect::kAll && (def.select == CutSelect::kComplete) != complete) {
      ++left_whole_;
      for (VertId v : tet) left_whole_box_.extend(geometry[v.index()]);
      continue;
    }
    if (p.split) {
      p.config = configs[i].key();
      resolve_split(p, tet, configs[i], edge_numbers[i], classifier, table);
    } else
      resolve_relabel(p, tet, classifier);
    pending_.push_back(p);
  }
  candidates_ = std::move(found);

  edge_point_ = {};  // indexes the scan's numbering, which number_points_by_key changes
  number_points_by_key();

  // Jobs: the fragments creating the pending tets, each with its tets. A
  // part's cuts also decompose the fragments that replace them: a coarse
  // tet may be crossed completely frames after the finer tets of its
  // region, which an earlier commit split (a single cut splits them alike).
  for (const Pending& p : pending_) {
    jobs_.push_back(mt.birth(p.tet));
    if (record && def.select != CutSelect::kFront && mt.death(p.tet).valid() && mt.death(p.tet) != mt.drain())
      jobs_.push_back(mt.death(p.tet));
  }
  sort_unique(jobs_, workspace_->id_bits);
  job_first_.assign(jobs_.size() + 1, 0);
  std::vector<std::uint32_t> job_index(pending_.size());
  // Each fragment's job through the workspace's map (set, read, reset with
  // nothing in between that can throw), not a binary search per tet.
  std::vector<std::int32_t>& job_of_fragment = workspace_->job_of_fragment;
  if (job_of_fragment.size() < mt.num_fragments()) job_of_fragment.resize(mt.num_fragments(), -1);
  for (std::size_t j = 0; j < jobs_.size(); ++j) job_of_fragment[jobs_[j].index()] = static_cast<std::int32_t>(j);
  for (std::size_t i = 0; i < pending_.size(); ++i) {
    job_index[i] = static_cast<std::uint32_t>(job_of_fragment[mt.birth(pending_[i].tet).index()]);
    ++job_first_[job_index[i] + 1];
  }
  for (FragId f : jobs_) job_of_fragment[f.index()] = -1;
  for (std::size_t j = 0; j < jobs_.size(); ++j) job_first_[j + 1] += job_first_[j];
  job_tets_.resize(pending_.size());
  std::vector<std::uint32_t> fill(job_first_.begin(), job_first_.end() - 1);
  for (std::size_t i = 0; i < pending_.size(); ++i) job_tets_[fill[job_index[i]]++] = static_cast<std::int32_t>(i);
  job_done_.assign(jobs_.size(), 0);
  // Last, when nothing can throw any more: the destructor resets these.
  std::vector<std::int32_t>& pending_of = workspace_->pending_of;
  if (pending_of.size() < mt.num_tets()) pending_of.resize(mt.num_tets(), -1);
  for (std::size_t i = 0; i < pending_.size(); ++i) pending_of[pending_[i].tet.index()] = static_cast<std::int32_t>(i);
  if (def.check_search && (def.search || def.grown_from || def.candidates)) check_search(mt, bvh, given, table);
  find_seconds_ = engine::seconds_since(start);
}

void MtCut::check_search(const Mt& mt, const TetBvh& bvh, std::span<const Vec3> geometry, SplitTable& table) const {
  MtCutDef whole = def_;
  whole.search = nullptr;
  whole.grown_from = nullptr;
  whole.candidates = nullptr;
  whole.check_search = false;
  const MtCut reference(mt, bvh, polygon_, geometry, whole, table);
  // (tet, 1 + configuration of a split or 0 for a relabel), sorted.
  const auto changes = [](const MtCut& cut) {
    std::vector<std::pair<std::int32_t, std::uint64_t>> out;
    out.reserve(cut.pending_.size());
    for (const Pending& p : cut.pending_) out.emplace_back(p.tet.value, p.split ? 1 + std::uint64_t{p.config} : 0);
    std::sort(out.begin(), out.end());
    return out;
  };
  const auto narrowed = changes(*this), walked = changes(reference);
  if (narrowed == walked) return;
  std::vector<std::pair<std::int32_t, std::uint64_t>> missed, extra;
  std::set_difference(walked.begin(), walked.end(), narrowed.begin(), narrowed.end(), std::back_inserter(missed));
  std::set_difference(narrowed.begin(), narrowed.end(), walked.begin(), walked.end(), std::back_inserter(extra));
  const auto first = [](const auto& v) {
    return v.empty() ? std::string("none") : "tet " + std::to_string(v.front().first);
  };
  throw std::logic_error("MtCut: the narrowed search changes " + std::to_string(narrowed.size()) +
                         " tets, a walk of the whole polygon " + std::to_string(walked.size()) + " (" +
                         std::to_string(missed.size()) + " missed, first " + first(missed) + "; " +
                         std::to_string(extra.size()) + " otherwise, first " + first(extra) + ")");
}

MtCut::~MtCut() {
  for (const Pending& p : pending_) workspace_->pending_of[p.tet.index()] = -1;
}

void MtCut::add_tets_around_on_vertices(const Mt& mt, const TetBvh& bvh, CutClassifier& classifier,
                                        const PartRecord* record, std::vector<TetId>& found) {
  // The cut may pass through a vertex that lies off the polygon's box (up to
  // the classifier's margin), and a tet around it must be classified with
  // the others: its other vertices may lie on the plane too, or make it
  // straddle. Each round walks the box of the vertices the last one put on
  // the cut (one walk: a progressive cut continuing the last one in its
  // plane puts hundreds on it) and adds the tets around them, which may put
  // more on. `found` stays sorted.
  std::vector<TetId> around, extra, merged;
  for (std::vector<VertId> on = classifier.take_new_on_vertices(); !on.empty();
       on = classifier.take_new_on_vertices()) {
    engine::Aabb at;
    for (VertId v : on) at.extend(mt.position(v));
    around.clear();
    bvh.for_each_overlapping(mt, at, [&](TetId t) {
      const Tet& tet = mt.tet(t);
      if (!(record && record->owns(t)) &&
          std::any_of(tet.begin(), tet.end(), [&](VertId v) { return classifier.on_so_far(v); }))
        around.push_back(t);
      return true;
    });
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    extra.clear();
    std::set_difference(around.begin(), around.end(), found.begin(), found.end(), std::back_inserter(extra));
    if (extra.empty()) break;
    for (TetId t : extra) classifier.add_candidate(mt.tet(t));
    merged.clear();
    std::merge(found.begin(), found.end(), extra.begin(), extra.end(), std::back_inserter(merged));
    found.swap(merged);
  }
}

bool MtCut::changes_earlier_pieces(const Mt& mt) const {
  return std::any_of(pending_.begin(), pending_.end(), [&](const Pending& p) { return mt.error_inherited(p.tet); });
}

std::size_t MtCut::job_cost(const Mt& mt, std::size_t job) const {
  if (job_done_[job]) return 0;
  std::size_t cost = 1;
  for (std::int32_t i : job_tets(job)) cost += !pending_[static_cast<std::size_t>(i)].done;
  for (TetId t : mt.replaced(jobs_[job])) {
    const std::int32_t i = pending_index(t);
    if (i >= 0 && !pending_[static_cast<std::size_t>(i)].done) ++cost;
  }
  return cost;
}

template <class Source>
VertId MtCut::point_id(const PointKey& key, Source&& source) {
  const auto [it, inserted] = point_index_.try_emplace(key, static_cast<std::int32_t>(points_.size()));
  if (inserted) points_.emplace_back(source()).key = key;
  return VertId(static_cast<std::int32_t>(first_vertex_) + it->second);
}

template <class Source>
VertId MtCut::edge_point_id(std::int32_t edge, const Tet& tet, Label label, Source&& source) {
  // A straddling edge's points are keyed by its number and the label's side
  // (none, negative, positive), never through point_index_.
  const std::size_t slot = 3 * static_cast<std::size_t>(edge) + static_cast<std::size_t>(label_side(label));
  if (slot >= edge_point_.size()) edge_point_.resize(std::max(slot + 1, 2 * edge_point_.size()), -1);
  std::int32_t& index = edge_point_[slot];
  if (index < 0) {
    index = static_cast<std::int32_t>(points_.size());
    points_.emplace_back(source()).key = point_key(tet, label);
  }
  return VertId(static_cast<std::int32_t>(first_vertex_) + index);
}

void MtCut::number_points_by_key() {
  // Ids follow the keys, not the scan: the scan's order is that of tet ids,
  // which follow the order the jobs of the last cut ran in. The keys are
  // sorted by value, packed into three words in key_less's order (an
  // indirect sort reads a scattered point per comparison), by radix.
  struct Packed {
    std::uint64_t kind_side, ids01, ids23;  // ids + 1 (>= 0) in 32 bits each
    std::int32_t index;
  };
  const auto pack = [](const PointKey& k, std::size_t index) {
    const auto id = [&](int i) { return static_cast<std::uint64_t>(static_cast<std::uint32_t>(k.ids[i] + 1)); };
    return Packed{static_cast<std::uint64_t>(k.kind) << 8 | static_cast<std::uint64_t>(k.side + 1), id(0) << 32 | id(1),
                  id(2) << 32 | id(3), static_cast<std::int32_t>(index)};
  };
  const std::size_t n = points_.size();
  std::vector<Packed> order;
  order.reserve(n);
  for (std::size_t i = 0; i < n; ++i) order.push_back(pack(points_[i].key, i));
  std::vector<Packed> scratch;
  engine::radix_sort<3>(order, scratch, [](const Packed& p) { return std::array{p.kind_side, p.ids01, p.ids23}; });
  // points_ stays in scan order (a point is ~120 bytes): add_vertices
  // reads it in key order through point_order_.
  std::vector<std::int32_t> rank(n);
  point_order_.resize(n);
  for (std::size_t r = 0; r < n; ++r) {
    const auto i = static_cast<std::size_t>(order[r].index);
    assert(r == 0 || key_less(points_[static_cast<std::size_t>(order[r - 1].index)].key, points_[i].key));
    rank[i] = static_cast<std::int32_t>(r);
    point_order_[r] = order[r].index;
  }
  const auto first = static_cast<std::int32_t>(first_vertex_);
  for (Tet& piece : piece_tets_)
    for (VertId& v : piece)
      if (v.value >= first) v = VertId(first + rank[static_cast<std::size_t>(v.value - first)]);
  point_index_.clear();  // holds the scan's numbering; not needed any more
}

void MtCut::resolve_split(Pending& p, const Tet& tet, const TetConfig& config,
                          const std::array<std::int32_t, 6>& edge_numbers, const CutClassifier& classifier,
                          SplitTable& table) {
  const SplitRecipe& recipe = table.recipe(config);
  assert(recipe.corner_slots.size() == recipe.tets.size());
  p.recipe = &recipe;
  p.first = static_cast<std::uint32_t>(piece_tets_.size());
  p.count = static_cast<std::uint8_t>(recipe.tets.size());
  // Each label's vertex once (it is a corner of several pieces); raw ids,
  // not VertIds, which would each be initialised.
  std::array<std::int32_t, kLabelCount> id_of;
  for (std::size_t k = 0; k < recipe.labels.size(); ++k) {
    const Label l = recipe.labels[k];
    if (label_kind(l) == LabelKind::kVertex && label_side(l) != LabelSide::kNeg) {
      id_of[k] = tet[label_index(l)].value;  // the vertex itself
    } else if (const VertId committed = def_.record ? def_.record->point(point_key(tet, l)) : VertId();
               committed.valid()) {
      id_of[k] = committed.value;  // a point of the part's committed crack
    } else if (const std::int32_t edge = label_kind(l) == LabelKind::kEdge ? edge_numbers[label_index(l)] : -1;
               edge >= 0) {
      id_of[k] = edge_point_id(edge, tet, l, [&] {
        return edge_point_source(tet, label_index(l), classifier.crossing_parameter_of(edge), classifier.positions());
      }).value;
    } else {
      id_of[k] = point_id(point_key(tet, l), [&] { return point_source(tet, l, classifier, recipe); }).value;
    }
  }
  for (const auto& slots : recipe.corner_slots)
    piece_tets_.push_back(
        {VertId(id_of[slots[0]]), VertId(id_of[slots[1]]), VertId(id_of[slots[2]]), VertId(id_of[slots[3]])});
  new_tets_ += recipe.tets.size();
}

void MtCut::resolve_relabel(Pending& p, const Tet& tet, const CutClassifier& classifier) {
  // Onto the negative copies of the vertices the cut passes through; a face
  // lying in the cut (all its vertices on it) becomes surface.
  Tet moved = tet;
  for (VertId& v : moved)
    if (splits(v)) {
      const VertId committed = def_.record ? def_.record->point(copy_key(v)) : VertId();
      const auto copy = [&] { return MadeVertex::at_vertex(v, classifier.positions()[v.index()]); };
      v = committed.valid() ? committed : point_id(copy_key(v), copy);
    }
  for (int f = 0; f < 4; ++f) {
    const auto& fv = kTetFaces[f];
    if (std::all_of(fv.begin(), fv.end(), [&](int c) { return is_on(classifier.state(tet[c])); }))
      p.on_faces = static_cast<std::uint8_t>(p.on_faces | 1u << f);
  }
  p.first = static_cast<std::uint32_t>(piece_tets_.size());
  p.count = 1;
  piece_tets_.push_back(moved);
}

void MtCut::add_vertices(Mt& mt, MtChangeReport& report) {
  if (mt.num_vertices() != first_vertex_)
    throw std::logic_error("MtCut: MT vertices were added between the start of the cut and its first job");
  mt.reserve(mt.num_vertices() + points_.size(), mt.num_tets() + new_tets_ + pending_.size());
  // The report's lists grow by what this cut makes, known now: once, not
  // by doublings over tens of thousands of entries (geometrically, should a
  // report gather many cuts).
  engine::reserve_geometric(report.made_vertices, report.made_vertices.size() + points_.size());
  engine::reserve_geometric(report.made_tets, report.made_tets.size() + new_tets_ + pending_.size());
  engine::reserve_geometric(report.replaced, report.replaced.size() + pending_.size());
  for (const std::int32_t index : point_order_) {
    MadeVertex& made = report.made_vertices.emplace_back(points_[static_cast<std::size_t>(index)]);
    made.rest = made.blend([&](VertId parent) { return mt.position(parent); });
    made.id = mt.add_vertex(made.rest);
  }
  report.counts.new_vertices += points_.size();
  vertices_added_ = true;
}

void MtCut::change_tet(Mt& mt, TetBvh& bvh, Pending& p, MtChangeReport& report) {
  assert(!p.done && mt.alive(p.tet));
  const TetId old = p.tet;
  const FaceMask mask = mt.boundary_mask(old);
  pieces_.clear();
  const std::span<const Tet> made(piece_tets_.data() + p.first, p.count);
  if (p.split) {
    piece_masks_.clear();
    for (std::size_t j = 0; j < made.size(); ++j) piece_masks_.push_back(piece_mask(p.recipe->faces[j], mask));
    const TetId first = mt.add_pieces(made, old, piece_masks_);
    for (std::size_t j = 0; j < made.size(); ++j) pieces_.emplace_back(first.index() + j);
    ++report.counts.split_tets;
    report.counts.new_tets += made.size();
  } else {
    pieces_.push_back(mt.add_piece(made[0], old, static_cast<FaceMask>(mask | p.on_faces)));
    ++report.counts.relabeled_tets;
  }
  const FragId birth = mt.birth(old), death = mt.death(old);
  mt.kill_tet(old);
  bvh.replace(mt, old, pieces_);
  report.replaced.push_back({old, birth, death, static_cast<std::uint32_t>(report.made_tets.size()),
                             static_cast<std::uint32_t>(pieces_.size()), p.config});
  report.made_tets.insert(report.made_tets.end(), pieces_.begin(), pieces_.end());
  p.done = true;
}

void MtCut::process(Mt& mt, TetBvh& bvh, std::size_t job, MtChangeReport& report) {
  if (job_done_[job]) throw std::logic_error("MtCut::process: job already done");
  const FragId f = jobs_[job];
  const auto start = Clock::now();
  if (!vertices_added_) {
    add_vertices(mt, report);
    // Every piece (and relabelled copy) joins the BVH: its arrays grow once.
    bvh.reserve(mt.num_tets() + new_tets_ + pending_.size(), new_tets_ + pending_.size());
  }
  // Step 2 for the tets f creates and, so that f sees its whole region
  // final, the pending tets it replaces (their own job will find them done).
  for (std::int32_t i : job_tets(job)) {
    Pending& p = pending_[static_cast<std::size_t>(i)];
    if (!p.done) change_tet(mt, bvh, p, report);
  }
  from_parents_.clear();
  for (TetId t : mt.replaced(f)) {
    const std::int32_t i = pending_index(t);
    if (i >= 0 && !pending_[static_cast<std::size_t>(i)].done) from_parents_.push_back(i);
  }
  for (std::int32_t i : from_parents_) change_tet(mt, bvh, pending_[static_cast<std::size_t>(i)], report);
  const auto dag_start = Clock::now();
  report.counts.split_seconds += std::chrono::duration<double>(dag_start - start).count();

  // Step 3: UpdateProcessFragment (not for a provisional cut, nor a part's
  // front: its partial splits separate nothing, and are taken back).
  if (f != mt.root() && f != mt.drain() && def_.decompose && def_.select != CutSelect::kFront) {
    Decomposition d = decompose_fragment(mt, f, workspace_->decomposition);
    if (d.outcome == DecomposeOutcome::kSplit) {
      ++report.counts.split_fragments;
      report.counts.new_fragments += d.parts.size() - 1;
      report.fragment_splits.push_back({f, std::move(d.parts)});
    } else if (d.outcome == DecomposeOutcome::kKeptWhole) {
      ++report.counts.whole_fragments;
    }
  }
  report.counts.dag_seconds += engine::seconds_since(dag_start);
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
    for (std::int32_t i : job_tets(j)) {
      const Pending& p = pending_[static_cast<std::size_t>(i)];
      if (p.done && mt.alive(p.tet)) report.add("MtCut: tet " + std::to_string(p.tet.value) + " changed but alive");
      if (!p.done && !mt.alive(p.tet)) report.add("MtCut: tet " + std::to_string(p.tet.value) + " pending but dead");
      if (!p.done && mt.birth(p.tet) != jobs_[j])
        report.add("MtCut: pending tet " + std::to_string(p.tet.value) + " left its job's fragment");
      if (job_done_[j] && !p.done) report.add("MtCut: job " + std::to_string(j) + " done with a pending tet");
    }
  }
  if (done != jobs_done_) report.add("MtCut: jobs done miscounted");
  for (std::size_t i = 0; i < pending_.size(); ++i)
    if (pending_index(pending_[i].tet) != static_cast<std::int32_t>(i))
      report.add("MtCut: tet " + std::to_string(pending_[i].tet.value) + " pending twice or not indexed");
  return report;
}

MtChangeReport cut_mt(Mt& mt, TetBvh& bvh, const CutPolygon& polygon, std::span<const Vec3> geometry,
                      const CutMtOptions& options, SplitTable* table, MtCutWorkspace* workspace) {
  SplitTable local(options.def.scheme);
  SplitTable& recipes = table ? *table : local;
  bvh.refresh(mt);  // before the search; the cut's own edits never rebuild it
  MtCut cut(mt, bvh, polygon, geometry, options.def, recipes, workspace);
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
