#include "engine/mt/selective_refinement.h"

#include <algorithm>

#include "engine/mt/tet_bvh.h"

namespace mtcut::engine {
namespace {

// The margin on a box's distances to the focus for a proof about the boxes
// inside it: the segment distances are within a few ulps of the exact ones
// (of the coordinates' size), not monotone under box inclusion bit for bit.
double proof_margin(const Aabb& box, const Segment& focus) {
  const double size = std::max({box.lo.cwiseAbs().maxCoeff(), box.hi.cwiseAbs().maxCoeff(),
                                focus.a.cwiseAbs().maxCoeff(), focus.b.cwiseAbs().maxCoeff()});
  return 1e-9 * (1.0 + size);
}

// +1: every fragment under a box with errors in [lo, hi] meets the field;
// -1: every one fails; 0: cannot tell. See the header for why this is sound.
int box_status(const Aabb& box, float lo, float hi, const ErrorField& field, const Segment& focus) {
  const double margin = proof_margin(box, focus);
  if (static_cast<double>(hi) <= field.threshold(min_distance(box, focus) - margin)) return 1;
  if (static_cast<double>(lo) > field.threshold(max_distance(box, focus) + margin)) return -1;
  return 0;
}

// Membership of S*, given each fragment's status.
std::vector<char> target_membership(const Mt& mt, const std::vector<FragId>& order, const std::vector<char>& meets) {
  std::vector<char> in(mt.num_fragments(), 0);
  for (FragId f : order) {
    if (f == mt.root()) {
      in[f.index()] = 1;
      continue;
    }
    if (f == mt.drain() || !meets[f.index()]) continue;
    bool parents_in = true;
    for (TetId t : mt.replaced(f)) parents_in = parents_in && in[mt.birth(t).index()];
    in[f.index()] = parents_in;
  }
  return in;
}

}  // namespace

bool tet_meets(const Mt& mt, TetId t, const ErrorField& field) {
  return static_cast<double>(mt.error(t)) <= field.threshold(min_distance(tet_box(mt, t), field.focus));
}

bool fragment_meets(const Mt& mt, FragId f, const ErrorField& field) {
  const auto created = mt.created(f);
  return std::all_of(created.begin(), created.end(), [&](TetId t) { return tet_meets(mt, t, field); });
}

std::vector<FragId> target_fragments(const Mt& mt, const ErrorField& field) {
  std::vector<char> meets(mt.num_fragments(), 0);
  for (std::size_t f = 0; f < mt.num_fragments(); ++f) meets[f] = fragment_meets(mt, FragId(f), field);
  const std::vector<char> in = target_membership(mt, mt.topological_order(), meets);
  std::vector<FragId> out;
  for (std::size_t f = 0; f < in.size(); ++f)
    if (in[f]) out.emplace_back(f);
  return out;
}

Frontier extract_frontier(const Mt& mt, const ErrorField& field) {
  return Frontier::from_fragments(mt, target_fragments(mt, field));
}

std::size_t SelectiveRefiner::bytes() const {
  return bvh_.bytes() + indexed_.capacity() * sizeof(FragId) + frag_box_.capacity() * sizeof(Aabb) +
         (node_min_.capacity() + node_max_.capacity()) * sizeof(float) + meets_.capacity() +
         summary_.capacity() * sizeof(FragmentSummary);
}

void SelectiveRefiner::summarize(const Mt& mt, FragId f, FragmentSummary& summary) {
  Aabb box;
  TetId worst = mt.created(f).front();
  for (TetId t : mt.created(f)) {
    box.extend(tet_box(mt, t));
    if (mt.error(t) > mt.error(worst)) worst = t;
  }
  summary.box = box;
  summary.worst_box = tet_box(mt, worst);
  summary.error = mt.error(worst);
  summary.computed = true;
}

std::vector<FragId> SelectiveRefiner::rebuild_index(const Mt& mt) {
  // What an index keeps of a fragment depends only on its created tets:
  // kept while created_revision says they did not change (in this MT).
  if (index_instance_ != mt.instance()) summary_.clear();
  index_instance_ = mt.instance();
  summary_.resize(mt.num_fragments());
  item_of_.assign(mt.num_fragments(), -1);
  std::vector<FragId> changed;
  indexed_.clear(), frag_box_.clear();
  for (std::size_t i = 0; i < mt.num_fragments(); ++i) {
    const FragId f(i);
    FragmentSummary& summary = summary_[i];
    if (summary.revision != mt.created_revision(f)) {
      changed.push_back(f);
      summary.revision = mt.created_revision(f);
      summary.computed = false;
    }
    if (f == mt.root() || f == mt.drain() || mt.created(f).empty()) continue;
    if (!summary.computed) summarize(mt, f, summary);
    item_of_[i] = static_cast<std::int32_t>(indexed_.size());
    indexed_.push_back(f);
    frag_box_.push_back(summary.box);
  }
  std::vector<std::int32_t> levels(indexed_.size());
  for (std::size_t i = 0; i < levels.size(); ++i) levels[i] = error_level(item_summary(i).error);
  bvh_.build(frag_box_, levels, 2);
  fit_nodes();
  index_revision_ = mt.revision();
  index_structure_ = mt.structure_revision();
  return changed;
}

std::optional<std::vector<FragId>> SelectiveRefiner::refit_index(const Mt& mt) {
  if (index_instance_ != mt.instance() || index_structure_ != mt.structure_revision() ||
      summary_.size() != mt.num_fragments())
    return std::nullopt;
  std::vector<FragId> changed;
  for (std::size_t i = 0; i < mt.num_fragments(); ++i)
    if (summary_[i].revision != mt.created_revision(FragId(i))) changed.emplace_back(i);
  for (FragId f : changed) {
    const bool indexed = f != mt.root() && f != mt.drain() && !mt.created(f).empty();
    if (indexed != (item_of_[f.index()] >= 0)) return std::nullopt;
  }
  for (FragId f : changed) {
    FragmentSummary& summary = summary_[f.index()];
    summary.revision = mt.created_revision(f);
    summary.computed = false;
    if (item_of_[f.index()] < 0) continue;
    summarize(mt, f, summary);
    frag_box_[static_cast<std::size_t>(item_of_[f.index()])] = summary.box;
  }
  // The tree's shape stays (built for boxes the cut's pieces lie within).
  fit_nodes();
  index_revision_ = mt.revision();
  return changed;
}

void SelectiveRefiner::fit_nodes() {
  // Bottom-up: children always follow their parent in the array.
  const auto nodes = bvh_.mutable_nodes();
  node_min_.assign(nodes.size(), 0.0f);
  node_max_.assign(nodes.size(), 0.0f);
  for (std::size_t n = nodes.size(); n-- > 0;) {
    BvhNode& node = nodes[n];
    if (node.leaf()) {
      const auto item = [&](std::int32_t k) { return static_cast<std::size_t>(bvh_.items()[static_cast<std::size_t>(k)]); };
      float lo = item_summary(item(node.first)).error, hi = lo;
      Aabb box;
      for (std::int32_t k = node.first; k < node.first + node.count; ++k) {
        const float e = item_summary(item(k)).error;
        lo = std::min(lo, e), hi = std::max(hi, e);
        box.extend(frag_box_[item(k)]);
      }
      node_min_[n] = lo, node_max_[n] = hi;
      node.box = box;
    } else {
      const auto l = static_cast<std::size_t>(node.first);
      node_min_[n] = std::min(node_min_[l], node_min_[l + 1]);
      node_max_[n] = std::max(node_max_[l], node_max_[l + 1]);
      Aabb box = nodes[l].box;
      box.extend(nodes[l + 1].box);
      node.box = box;
    }
  }
}

bool SelectiveRefiner::holds_what_it_left(const Frontier& frontier) const {
  if (frontier.fragments().size() != left_.size()) return false;
  return std::all_of(left_.begin(), left_.end(), [&](FragId f) { return frontier.contains(f); });
}

SelectiveRefiner::Stats SelectiveRefiner::update(const Mt& mt, const ErrorField& field, Frontier& frontier) {
  Stats stats;
  // After the MT changed, meets_ still holds the status under last_field_
  // of every fragment whose created tets did not change.
  std::vector<FragId> changed;
  bool carried = have_last_ && last_field_.same_shape(field) && meets_.size() <= mt.num_fragments();
  bool refitted = false;
  if (index_revision_ != mt.revision() || index_instance_ != mt.instance()) {
    carried = carried && index_instance_ == mt.instance();
    std::optional<std::vector<FragId>> refit;
    if (carried && meets_.size() == mt.num_fragments()) refit = refit_index(mt);
    refitted = refit.has_value();
    changed = refitted ? std::move(*refit) : rebuild_index(mt);
    have_last_ = false;
  }
  frontier.sync(mt);
  const bool incremental = have_last_ && mt_revision_ == mt.revision() &&
                           frontier_version_ == frontier.version() && last_field_.same_shape(field);
  if (incremental) {
    incremental_update(mt, field, frontier, stats);
  } else if (refitted && holds_what_it_left(frontier)) {
    follow_cut_update(mt, field, frontier, stats, changed);
    stats.followed_cut = true;
  } else {
    full_update(mt, field, frontier, stats, carried ? &changed : nullptr);
  }
  stats.incremental = incremental;
  last_field_ = field;
  have_last_ = true;
  mt_revision_ = mt.revision();
  frontier_version_ = frontier.version();
  left_.assign(frontier.fragments().begin(), frontier.fragments().end());
  return stats;
}

void SelectiveRefiner::full_update(const Mt& mt, const ErrorField& field, Frontier& frontier, Stats& stats,
                                    const std::vector<FragId>* changed) {
  if (changed) {
    // The others' status moves with the focus as in an incremental update;
    // the changed ones' is found from scratch (after: the walk may have set
    // it from a stale status).
    meets_.resize(mt.num_fragments(), 0);
    follow_focus(mt, field, stats);
    for (FragId f : *changed) meets_[f.index()] = fragment_meets(mt, f, field);
    stats.fragments_tested += changed->size();
  } else {
    meets_.assign(mt.num_fragments(), 0);
    for (std::size_t f = 0; f < mt.num_fragments(); ++f) meets_[f] = fragment_meets(mt, FragId(f), field);
    stats.fragments_tested = mt.num_fragments();
  }
  const std::vector<FragId> order = mt.topological_order();
  const std::vector<char> in = target_membership(mt, order, meets_);
  // Leave S \ S* children first, then enter S* \ S parents first: every
  // step is a valid refine / coarsen because both sets are parent-closed.
  for (auto it = order.rbegin(); it != order.rend(); ++it)
    if (frontier.contains(*it) && !in[it->index()]) {
      frontier.refine(mt, *it);
      ++stats.refined;
    }
  for (FragId f : order)
    if (in[f.index()] && !frontier.contains(f)) {
      frontier.coarsen(mt, f);
      ++stats.coarsened;
    }
}

void SelectiveRefiner::incremental_update(const Mt& mt, const ErrorField& field, Frontier& frontier, Stats& stats) {
  follow_focus(mt, field, stats);
  apply_status_changes(mt, frontier, stats);
}

void SelectiveRefiner::follow_cut_update(const Mt& mt, const ErrorField& field, Frontier& frontier, Stats& stats,
                                         const std::vector<FragId>& changed) {
  // The frontier is S* of the statuses before the cut (the same fragments,
  // the same DAG): the others' move with the focus; the changed ones' are
  // tested from scratch and listed where they differ from before.
  std::vector<char> before(changed.size());
  for (std::size_t i = 0; i < changed.size(); ++i) before[i] = meets_[changed[i].index()];
  follow_focus(mt, field, stats);
  for (std::size_t i = 0; i < changed.size(); ++i) meets_[changed[i].index()] = fragment_meets(mt, changed[i], field);
  stats.fragments_tested += changed.size();
  // The walk lists a changed fragment it tested (by the same test) against
  // its status before: listed once, here or there.
  for (std::size_t i = 0; i < changed.size(); ++i) {
    const FragId f = changed[i];
    // The root is always in S* and the drain never (target_membership).
    if (meets_[f.index()] == before[i] || f == mt.root() || f == mt.drain()) continue;
    std::vector<FragId>& list = meets_[f.index()] ? changed_good_ : changed_bad_;
    if (std::find(list.begin(), list.end(), f) == list.end()) list.push_back(f);
  }
  apply_status_changes(mt, frontier, stats);
#ifndef NDEBUG
  const std::vector<FragId> target = target_fragments(mt, field);
  assert(target.size() == frontier.fragments().size() &&
         std::all_of(target.begin(), target.end(), [&](FragId f) { return frontier.contains(f); }));
#endif
}

void SelectiveRefiner::apply_status_changes(const Mt& mt, Frontier& frontier, Stats& stats) {
  // Fragments that now fail leave, and everything that depends on them.
  for (FragId f : changed_bad_)
    if (frontier.contains(f)) refine_with_descendants(mt, f, frontier, stats);
  // Fragments that now meet enter once their parents are in; their children
  // may follow.
  queue_.assign(changed_good_.begin(), changed_good_.end());
  while (!queue_.empty()) {
    const FragId f = queue_.back();
    queue_.pop_back();
    if (!meets_[f.index()] || !frontier.can_coarsen(mt, f)) continue;
    frontier.coarsen(mt, f);
    ++stats.coarsened;
    for (FragId c : mt.children(f))
      if (c != mt.drain() && meets_[c.index()]) queue_.push_back(c);
  }
}

void SelectiveRefiner::follow_focus(const Mt& mt, const ErrorField& field, Stats& stats) {
  const Segment from = last_field_.focus, to = field.focus;
  changed_bad_.clear(), changed_good_.clear();
  const auto nodes = bvh_.nodes();
  const auto unchanged = [&](const Aabb& box, float lo, float hi) {
    const int before = box_status(box, lo, hi, field, from);
    return before != 0 && before == box_status(box, lo, hi, field, to);
  };
  bvh_.walk(
      [&](std::int32_t n) {
        ++stats.nodes_visited;
        const auto i = static_cast<std::size_t>(n);
        return !unchanged(nodes[i].box, node_min_[i], node_max_[i]);
      },
      [&](std::int32_t n) {
        const BvhNode& node = nodes[static_cast<std::size_t>(n)];
        for (std::int32_t k = node.first; k < node.first + node.count; ++k) {
          const auto item = static_cast<std::size_t>(bvh_.items()[static_cast<std::size_t>(k)]);
          const FragmentSummary& summary = item_summary(item);
          if (unchanged(summary.box, summary.error, summary.error)) continue;
          // The largest-error tet decides "fails" exactly (tet_meets' own test).
          const double e = summary.error;
          const bool fails_before = e > field.threshold(min_distance(summary.worst_box, from));
          const bool fails_after = e > field.threshold(min_distance(summary.worst_box, to));
          if (fails_before && fails_after) continue;
          const FragId f = indexed_[item];
          ++stats.fragments_tested;
          const char now = fragment_meets(mt, f, field);
          if (now == meets_[f.index()]) continue;
          meets_[f.index()] = now;
          ++stats.status_changes;
          (now ? changed_good_ : changed_bad_).push_back(f);
        }
        return true;
      });
}

void SelectiveRefiner::refine_with_descendants(const Mt& mt, FragId f, Frontier& frontier, Stats& stats) {
  // Post-order over the part of S below f: a fragment leaves after all its
  // children in S have.
  std::vector<std::pair<FragId, bool>> stack = {{f, false}};
  while (!stack.empty()) {
    const auto [g, expanded] = stack.back();
    stack.pop_back();
    if (!frontier.contains(g)) continue;
    if (expanded) {
      frontier.refine(mt, g);
      ++stats.refined;
      continue;
    }
    stack.emplace_back(g, true);
    for (FragId c : mt.children(g))
      if (frontier.contains(c)) stack.emplace_back(c, false);
  }
}

}  // namespace mtcut::engine
