#pragma once
// Selective refinement: the frontier that a position-dependent error
// threshold asks for, reached incrementally as the focus (the scalpel's
// blade, a segment) moves.
//
// The threshold. At distance d from the focus, tets may have error up to
//     threshold(d) = near_error + growth * max(0, d - radius)
// (uniform when growth = 0). A tet meets the field when e(t) <= threshold(d),
// d measured from the focus to the tet's bounding box (their nearest
// points, segment_distance.h). A fragment meets it when every tet it
// creates does.
//
// The target. S* = the fragments f such that f and all its ancestors meet
// the field: the largest parent-closed set of fragments that all meet it,
// i.e. the coarsest frontier every tet of which (the fine ones aside) meets
// the field. It is unique, so an incremental update and an extraction from
// scratch can and must agree exactly. Uniform error 0 gives the fine mesh,
// +inf the coarsest.
//
// Why incremental. When the focus moves from c0 to c1, a fragment can change
// status only if some tet of it meets the field at one focus and not at the
// other. A BVH over fragments, each node carrying the least and largest
// fragment error below it, proves for whole subtrees that every fragment
// meets (largest error <= threshold at the nearest distance) or fails
// (least error > threshold at the farthest distance) at both foci, and
// skips them. The proofs take the distances with a margin far above their
// rounding, so that a box inside the node is never nearer (farther) than
// the node's bound once both are rounded. A fragment itself also keeps the
// box of its largest-error tet: that tet fails exactly when the focus is
// within its own reach, which settles most fragments near the focus
// without looking at their tets.
// Then S moves from S*(c0) to S*(c1): fragments that now fail
// are refined away with their descendants, fragments that now meet are
// added when their parents are in, and their children after them.

#include <cstdint>
#include <optional>
#include <vector>

#include "engine/mt/bvh.h"
#include "engine/mt/frontier.h"
#include "engine/mt/mt.h"
#include "engine/mt/segment_distance.h"

namespace mtcut::engine {

struct ErrorField {
  Segment focus;            // the scalpel's blade (a point when its ends are equal)
  double radius = 0.0;      // within it, near_error applies
  double near_error = 0.0;  // error allowed at the focus (metres)
  double growth = 0.0;      // error allowed per metre beyond the radius (>= 0)

  static ErrorField uniform(double max_error) {
    ErrorField field;
    field.near_error = max_error;
    return field;
  }
  // The scalpel's field: the fine mesh within `radius` of `focus`, then
  // tets of error (enclosing radius) up to growth x the distance beyond it.
  static ErrorField around(const Segment& focus, double radius, double growth = 0.25) {
    ErrorField field;
    field.focus = focus;
    field.radius = radius;
    field.growth = growth;
    return field;
  }
  double threshold(double distance) const {
    return near_error + growth * std::max(0.0, distance - radius);
  }
  // Same threshold function around a possibly different focus.
  bool same_shape(const ErrorField& o) const {
    return radius == o.radius && near_error == o.near_error && growth == o.growth;
  }
};

bool tet_meets(const Mt& mt, TetId t, const ErrorField& field);
bool fragment_meets(const Mt& mt, FragId f, const ErrorField& field);

// S* (see above), ascending.
std::vector<FragId> target_fragments(const Mt& mt, const ErrorField& field);
// The frontier of S*, from scratch.
Frontier extract_frontier(const Mt& mt, const ErrorField& field);
// Every tet of error <= max_error where the MT has one: 0 the fine mesh,
// +inf the coarsest.
inline Frontier extract_uniform(const Mt& mt, double max_error) {
  return extract_frontier(mt, ErrorField::uniform(max_error));
}

class SelectiveRefiner {
 public:
  struct Stats {
    bool incremental = false;         // false: a full pass was needed
    bool followed_cut = false;        // no full pass after a cut that left the DAG as it was
    std::size_t nodes_visited = 0;    // BVH nodes looked at
    std::size_t fragments_tested = 0;
    std::size_t status_changes = 0;
    std::size_t refined = 0;
    std::size_t coarsened = 0;
  };

  // Moves `frontier` to S*(field). Incremental when the MT, the frontier and
  // the field's shape are as this refiner's previous call left them (only
  // the focus moved). After a cut that left the fragments' DAG as it was
  // (Mt::structure_revision) and the frontier's fragments as this refiner
  // left them (the cut followed in place), incremental too: the index is
  // refitted to the fragments whose created tets changed
  // (Mt::created_revision), their status is found again, and they join the
  // fragments whose status the focus's move changed. Otherwise one full
  // pass over the fragments, which after a cut re-indexes and re-tests only
  // the changed fragments: the others' status follows the focus as in an
  // incremental update, from the last call's, which is exact for them.
  Stats update(const Mt& mt, const ErrorField& field, Frontier& frontier);
  std::size_t bytes() const;

 private:
  // Re-indexes; returns the fragments whose created tets changed since the
  // last index (all of them the first time).
  std::vector<FragId> rebuild_index(const Mt& mt);
  // The index's boxes and error bounds, refitted to the fragments whose
  // created tets changed since it was built or refitted, which are
  // returned; nullopt when that is not enough (the DAG changed, or a
  // fragment came to create tets or stopped to): rebuild_index then.
  std::optional<std::vector<FragId>> refit_index(const Mt& mt);
  // The node boxes and error bounds, from the items' up.
  void fit_nodes();
  // The fragments of `frontier` are those this refiner's last call left.
  bool holds_what_it_left(const Frontier& frontier) const;
  // `changed`: when not null, meets_ holds every other fragment's status
  // under last_field_, and only these are tested from scratch.
  void full_update(const Mt& mt, const ErrorField& field, Frontier& frontier, Stats& stats,
                   const std::vector<FragId>* changed);
  // meets_ of the fragments whose status may differ between the last
  // field's focus and field's (the BVH walk of an incremental update),
  // listing them in changed_good_ / changed_bad_.
  void follow_focus(const Mt& mt, const ErrorField& field, Stats& stats);
  void incremental_update(const Mt& mt, const ErrorField& field, Frontier& frontier, Stats& stats);
  // After a cut (see update): `changed` fragments re-tested beside the focus's move.
  void follow_cut_update(const Mt& mt, const ErrorField& field, Frontier& frontier, Stats& stats,
                         const std::vector<FragId>& changed);
  // The frontier follows the fragments listed in changed_bad_ / changed_good_.
  void apply_status_changes(const Mt& mt, Frontier& frontier, Stats& stats);
  void refine_with_descendants(const Mt& mt, FragId f, Frontier& frontier, Stats& stats);

  Bvh bvh_;                         // over indexed fragments
  std::vector<FragId> indexed_;     // (n_items) fragment of each BVH item
  std::vector<Aabb> frag_box_;      // (n_items) box of its created tets (what the BVH is built over)
  std::vector<float> node_min_;     // (n_nodes) least fragment error below
  std::vector<float> node_max_;     // (n_nodes) largest fragment error below
  std::vector<char> meets_;         // (n_fragments) status under last_field_
  // (n_fragments) what the index holds of each fragment, and the
  // created_revision it was taken at: re-indexing reuses it when unchanged.
  struct FragmentSummary {
    std::uint64_t revision = ~std::uint64_t{0};
    bool computed = false;  // box, worst_box and error hold its created tets'
    Aabb box, worst_box;
    float error = 0.0f;
  };
  std::vector<FragmentSummary> summary_;
  std::vector<std::int32_t> item_of_;  // (n_fragments) its BVH item, -1 when not indexed
  // BVH item `item`'s fragment's summary.
  const FragmentSummary& item_summary(std::size_t item) const { return summary_[indexed_[item].index()]; }
  // (Re)computes a summary from f's created tets.
  static void summarize(const Mt& mt, FragId f, FragmentSummary& summary);
  std::uint64_t index_instance_ = 0;  // the Mt::instance() the index and summary_ are of
  ErrorField last_field_;
  bool have_last_ = false;
  std::uint64_t mt_revision_ = 0;
  std::uint64_t index_revision_ = ~std::uint64_t{0};
  std::uint64_t index_structure_ = ~std::uint64_t{0};  // the Mt::structure_revision() indexed
  std::vector<FragId> left_;  // the frontier's fragments the last call left
  std::uint64_t frontier_version_ = 0;
  std::vector<FragId> changed_bad_, changed_good_, queue_;  // scratch
};

}  // namespace mtcut::engine
