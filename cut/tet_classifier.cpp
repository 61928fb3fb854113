#include "cut/tet_classifier.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>
#include <string>

#include "engine/tet_geometry.h"

namespace mtcut::cut {

using engine::kTetEdges;
using engine::Vec3;

const char* case_name(CutCase c) {
  switch (c) {
    case CutCase::kA: return "A";
    case CutCase::kB: return "B";
    case CutCase::kC: return "C";
    case CutCase::kD: return "D";
    case CutCase::kE: return "E";
    case CutCase::kO: return "O";
    case CutCase::kVertex: return "vertex";
    case CutCase::kCount: break;
  }
  return "?";
}

// ---- TetConfig ---------------------------------------------------------------

bool TetConfig::straddles(int edge) const {
  const VertexState a = vertex[kTetEdges[edge][0]], b = vertex[kTetEdges[edge][1]];
  return is_strict(a) && is_strict(b) && a != b;
}

bool TetConfig::is_cut() const {
  bool neg = false, pos = false, active_on = false;
  for (VertexState s : vertex) {
    neg |= s == VertexState::kNeg;
    pos |= s == VertexState::kPos;
    active_on |= s == VertexState::kOnActive;
  }
  for (int k = 0; k < 6; ++k)
    if (edge_active(k)) return true;
  return active_on && neg && pos;
}

std::uint32_t TetConfig::key() const {
  std::uint32_t key = 0;
  for (int i = 0; i < 4; ++i) key |= static_cast<std::uint32_t>(vertex[i]) << (2 * i);
  for (int k = 0; k < 6; ++k)
    if (edge_active(k)) key |= 1u << (8 + k);
  // Lehmer code of the id order: 4 * 3 * 2 = 24 values in 5 bits.
  int code = 0;
  for (int i = 0; i < 3; ++i) {
    int smaller = 0;
    for (int j = i + 1; j < 4; ++j) smaller += rank[j] < rank[i];
    code = code * (4 - i) + smaller;
  }
  key |= static_cast<std::uint32_t>(code) << 14;
  const bool on = std::any_of(vertex.begin(), vertex.end(), is_on);
  if (bent && !on) key |= 1u << 19;
  return key;
}

CutCase TetConfig::cut_case() const {
  int neg = 0, pos = 0;
  for (VertexState s : vertex) {
    if (is_on(s)) return CutCase::kVertex;
    neg += s == VertexState::kNeg;
    pos += s == VertexState::kPos;
  }
  int active = 0, sum = 0;
  for (int k = 0; k < 6; ++k)
    if (edge_active(k)) {
      ++active;
      sum += k;
    }
  if (neg == 1 || pos == 1) return active == 3 ? CutCase::kA : active == 2 ? CutCase::kD : CutCase::kC;
  switch (active) {
    case 4: return CutCase::kB;
    case 3: return CutCase::kE;
    case 2: return sum == 5 ? CutCase::kO : CutCase::kD;  // opposite edges are k and 5 - k
    default: return CutCase::kC;
  }
}

// ---- CutClassifier -----------------------------------------------------------

CutClassifier::CutClassifier(const CutPolygon& polygon, std::span<const Vec3> positions, const ClassifierDef& def,
                             Scratch* scratch, const CutContinuation* continuation)
    : polygon_(polygon),
      positions_(positions),
      continuation_(continuation),
      snap_(ClassifierDef::effective_snap(def.snap)),
      face_clamp_(ClassifierDef::face_clamp(def.snap)),
      own_scratch_(scratch ? nullptr : std::make_unique<Scratch>()),
      scratch_(scratch ? scratch : own_scratch_.get()) {
  if (scratch_->in_use) throw std::logic_error("CutClassifier: the scratch is in use by another classifier");
  scratch_->in_use = true;
  if (scratch_->info.size() < positions.size()) scratch_->info.resize(positions.size());
  if (scratch_->code.size() < positions.size()) scratch_->code.resize(positions.size(), 0);
  if (continuation_) {
    // The stroke's front that lies on the polygon (to kMinSnap of its face,
    // as the leading edge put it) is split: the crack goes on from it.
    for (const CrackFrontPoint& f : continuation_->front) {
      double longest = 0;
      for (int i = 0; i < 3; ++i)
        longest = std::max(longest, (positions_[f.face[i].index()] - positions_[f.face[(i + 1) % 3].index()]).norm());
      const Vec3& p = positions_[f.id.index()];
      const double reach = (ClassifierDef::kMinSnap + 1e-9) * longest;
      if (polygon_.distance_outside(p) > reach || std::abs(polygon_.signed_distance(p)) > reach) {
        // Elsewhere on the sheet (where the blade's tip ended a step) the
        // crack ends at it: on the cut, not split, whatever side rounding
        // puts it on, so no cut point is made next to it.
        if (std::abs(distance(f.id)) <= reach) edit(f.id).crack_end = true;
        continue;
      }
      edit(f.id).pulled = true;
      put_on(f.id);
    }
  }
}

void CutClassifier::Scratch::reserve(std::size_t vertices) {
  if (in_use) throw std::logic_error("CutClassifier::Scratch::reserve: a classifier holds it");
  if (info.size() < vertices) info.resize(vertices);
  if (code.size() < vertices) code.resize(vertices, 0);
}

engine::ValidationReport CutClassifier::Scratch::validate() const {
  engine::ValidationReport report;
  if (in_use) report.add("CutClassifier::Scratch: still held by a classifier");
  if (!dirty.empty()) report.add("CutClassifier::Scratch: " + std::to_string(dirty.size()) + " entries listed dirty");
  for (std::size_t v = 0; v < info.size(); ++v)
    if (!(info[v] == VertexInfo{})) report.add("CutClassifier::Scratch: vertex " + std::to_string(v) + " not reset");
  for (std::size_t v = 0; v < code.size(); ++v)
    if (code[v] != 0) report.add("CutClassifier::Scratch: vertex " + std::to_string(v) + " left coded");
  return report;
}

CutClassifier::~CutClassifier() {
  for (VertId v : touched_) scratch_->code[v.index()] = 0;
  for (VertId v : scratch_->dirty) scratch_->info[v.index()] = VertexInfo{};
  scratch_->dirty.clear();
  scratch_->in_use = false;
}

std::uint64_t CutClassifier::edge_key(VertId a, VertId b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a.value, b.value));
  const auto hi = static_cast<std::uint32_t>(std::max(a.value, b.value));
  return static_cast<std::uint64_t>(lo) << 32 | hi;
}

std::int8_t CutClassifier::compute_side(VertId v) const {
  VertexInfo& info = edit(v);
  const Vec3& p = positions_[v.index()];
  if (continuation_ && !continuation_->junctions.empty() && continuation_->last().ahead(p) < 0) {  // behind
    const CutPolygon& previous = continuation_->polygon_behind(p);
    info.distance = previous.signed_distance(p);
    if (const CrackSides* sides = continuation_->sides) {
      if (const auto it = sides->find(v.value); it != sides->end()) {
        info.raw = it->second;
        info.crack_sided = true;
        info.vetoed = true;  // never snapped onto the cut: it lies in the crack, on its side
        return info.raw;
      }
    }
    info.raw = static_cast<std::int8_t>(previous.side(p));
    return info.raw;
  }
  info.raw = static_cast<std::int8_t>(polygon_.side(p));
  info.distance = polygon_.signed_distance(p);
  return info.raw;
}

double CutClassifier::distance(VertId v) const {
  raw_side(v);
  return at(v).distance;
}

std::int8_t CutClassifier::side_for_crossings(VertId v) const {
  if (at(v).pulled) return 0;
  const std::int8_t raw = raw_side(v);
  return raw == 0 && at(v).vetoed ? 1 : raw;  // a vetoed vertex on the plane counts as positive
}

void CutClassifier::pull_in(VertId v) {
  assert(touched_.empty());
  if (!at(v).requested_off) edit(v).pulled = true;
}

double CutClassifier::raw_parameter(VertId a, VertId b) const {
  const VertId lo = a < b ? a : b, hi = a < b ? b : a;
  double d_lo = distance(lo);
  double d_hi = distance(hi);
  if (continuation_) {
    // An edge crossing the polygon's plane is cut where it crosses it, as
    // in every other resolution; only an edge that straddles the sheet
    // behind the junction alone (never covered) is placed by the sheet.
    const double p_lo = polygon_.signed_distance(positions_[lo.index()]);
    const double p_hi = polygon_.signed_distance(positions_[hi.index()]);
    if ((p_lo < 0 && p_hi > 0) || (p_lo > 0 && p_hi < 0)) {
      d_lo = p_lo;
      d_hi = p_hi;
    }
  }
  const double t = d_lo - d_hi != 0 ? d_lo / (d_lo - d_hi) : 0.5;
  return std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.5;
}

void CutClassifier::veto(VertId v) {
  assert(touched_.empty());
  VertexInfo& info = edit(v);
  info.vetoed = true;
  info.requested_off = true;
}

std::array<std::int8_t, 4> CutClassifier::crossing_sides(const Tet& tet) const {
  std::array<std::int8_t, 4> s;
  for (int i = 0; i < 4; ++i) s[i] = side_for_crossings(tet[i]);
  return s;
}

bool CutClassifier::one_sided(const std::array<std::int8_t, 4>& s) {
  return s[0] != 0 && s[0] == s[1] && s[1] == s[2] && s[2] == s[3];
}

bool CutClassifier::may_be_cut(const Tet& tet) const { return !one_sided(crossing_sides(tet)); }

bool CutClassifier::add_candidate(const Tet& tet) {
  assert(!finalized_);
  const std::array<std::int8_t, 4> s = crossing_sides(tet);
  if (one_sided(s)) return false;

  std::array<double, 4> d;
  for (int i = 0; i < 4; ++i) d[i] = distance(tet[i]);  // crossing_sides computed them
  std::array<double, 4> reach2{};  // longest edge at each corner, squared
  for (int k = 0; k < 6; ++k) {
    const int a = kTetEdges[k][0], b = kTetEdges[k][1];
    const double length2 = std::max((positions_[tet[a].index()] - positions_[tet[b].index()]).squaredNorm(),
                                    std::numeric_limits<double>::min());
    reach2[a] = std::max(reach2[a], length2);
    reach2[b] = std::max(reach2[b], length2);
  }
  for (int i = 0; i < 4; ++i) {
    VertexInfo& info = edit(tet[i]);
    if (info.reach2 == 0) touched_.push_back(tet[i]);
    info.reach2 = std::max(info.reach2, reach2[i]);
    for (int j = 0; j < 4; ++j)
      if (j != i) info.lean += d[j];
    if (s[i] == 0) put_on(tet[i]);  // vetoed vertices on the plane count as positive (s = 1)
  }
  // The parameter straight from the ends' cached distances: the edge table
  // is filled by configure, once the states are final (a look-up per
  // straddling edge here cost as much again on Table 1's largest cut).
  for (int k = 0; k < 6; ++k) {
    const VertId a = tet[kTetEdges[k][0]], b = tet[kTetEdges[k][1]];
    if (s[kTetEdges[k][0]] * s[kTetEdges[k][1]] >= 0) continue;
    const double t = raw_parameter(a, b);
    const VertId lo = a < b ? a : b, hi = a < b ? b : a;
    if (t < snap_ && !at(lo).vetoed) put_on(lo);
    if (t > 1 - snap_ && !at(hi).vetoed) put_on(hi);
  }
  return true;
}

void CutClassifier::put_on(VertId v) {
  if (at(v).on) return;
  VertexInfo& info = edit(v);
  info.on = true;
  new_on_.push_back(v);
}

std::vector<VertId> CutClassifier::take_new_on_vertices() {
  assert(!finalized_);
  std::vector<VertId> out;
  out.swap(new_on_);
  return out;
}

void CutClassifier::keep_off(VertId v) {
  VertexInfo& info = edit(v);
  info.vetoed = true;
  const double d = distance(v);
  if (info.crack_sided) return;  // its crack's side
  // On the plane to rounding: the side its neighbours are on.
  if (raw_side(v) == 0 || std::abs(d) <= 1e-9 * reach(v)) {
    info.kept_side = info.lean < 0 ? -1 : 1;
    if (info.kept_side != raw_side(v)) resided_.push_back(v);
  }
}

void CutClassifier::finalize() {
  assert(!finalized_);
  finalized_ = true;
  for (VertId v : touched_) {
    VertexInfo& info = edit(v);
    if (info.vetoed) keep_off(v);
    if (!info.on) continue;
    const Vec3& p = positions_[v.index()];
    // The margin covers face points of an earlier cut, which sit up to
    // face_clamp of their segment off its outline, so that the next stroke
    // continuing the incision splits them.
    info.active = info.pulled || polygon_.projects_inside(p) >= 0 ||
                  polygon_.distance_outside(p) <= ClassifierDef::margin_fraction(snap_) * reach(v);
    if (!info.active) {
      // On the plane but off the polygon: not split; it stays on its side
      // and cut points keep off it.
      info.on = false;
      keep_off(v);
      continue;
    }
    on_vertices_.push_back(v);
  }
  // States are final: each candidate vertex's in a byte (state()).
  for (VertId v : touched_)
    scratch_->code[v.index()] =
        static_cast<std::uint8_t>((1 + static_cast<int>(uncoded_state(v))) | (at(v).vetoed ? 4 : 0));
}

VertexState CutClassifier::uncoded_state(VertId v) const {
  const VertexInfo& info = at(v);
  if (finalized_ && info.on) return VertexState::kOnActive;
  if (info.crack_end) return VertexState::kOnInactive;
  if (info.kept_side != 0) return info.kept_side < 0 ? VertexState::kNeg : VertexState::kPos;
  // Exactly on the plane but kept off the cut, or never part of a candidate
  // (far from the cut): positive.
  return raw_side(v) < 0 ? VertexState::kNeg : VertexState::kPos;
}

bool CutClassifier::snapped(VertId v) const {
  const VertexInfo& info = at(v);
  return info.on && (info.raw != 0 || info.pulled);
}

bool CutClassifier::vetoed(VertId v) const { return at(v).vetoed; }
bool CutClassifier::veto_requested(VertId v) const { return at(v).requested_off; }

CutClassifier::EdgeInfo& CutClassifier::edge(VertId a, VertId b) const {
  auto [it, fresh] = edges_.try_emplace(edge_key(a, b));
  if (fresh) {
    it->second.number = static_cast<std::int32_t>(edges_.size() - 1);
    edge_t_.push_back(raw_parameter(a, b));
  }
  return it->second;
}

double CutClassifier::crossing_parameter(VertId a, VertId b) const {
  // (An edge met first here is one at a vertex kept off the plane.) Every
  // cut point stays `snap` away from the edge's ends: snapping makes that so
  // for the ends on the cut; an end kept off it, or sided by its neighbours
  // while on the plane, keeps the point away this way.
  return crossing_parameter_of(edge(a, b).number);
}

bool CutClassifier::crossing_covered(VertId a, VertId b) const { return covered(edge(a, b), a, b); }

bool CutClassifier::covered(EdgeInfo& e, VertId a, VertId b) const {
  if (e.covered < 0) {
    const VertId lo = a < b ? a : b, hi = a < b ? b : a;
    // Closed: a crossing on the outline is cut, so strokes sharing an edge
    // leave nothing between them. Behind a stroke's junction an edge may
    // straddle the sheet and not the plane: the line through it may then
    // meet the polygon, the edge not.
    const Vec3 &p_lo = positions_[lo.index()], &p_hi = positions_[hi.index()];
    if (!continuation_) {
      // The ends' distances to this polygon's plane are cached: a filter
      // decides most edges without orient3d.
      e.covered = polygon_.segment_crossing(p_lo, p_hi, distance(lo), distance(hi)) >= 0 ? 1 : 0;
      return e.covered == 1;
    }
    const bool crosses_plane = polygon_.side(p_lo) * polygon_.side(p_hi) < 0;
    e.covered = crosses_plane && polygon_.line_crossing(p_lo, p_hi) >= 0 ? 1 : 0;
  }
  return e.covered == 1;
}

VertexState CutClassifier::side_of_uncut(const Tet& tet) const {
  for (VertId v : tet) {
    const VertexState s = state(v);
    if (is_strict(s)) return s;
  }
  double lean = 0;
  for (VertId v : tet) lean += polygon_.signed_distance(positions_[v.index()]);
  return lean < 0 ? VertexState::kNeg : VertexState::kPos;
}

TetConfig CutClassifier::configure(const Tet& tet) const {
  std::array<std::int32_t, 6> unused;
  return configure(tet, unused);
}

TetConfig CutClassifier::configure(const Tet& tet, std::array<std::int32_t, 6>& edge_numbers) const {
  TetConfig config;
  for (int i = 0; i < 4; ++i) {
    config.vertex[i] = state(tet[i]);
    config.bent |= is_on(config.vertex[i]) || coded_vetoed(tet[i]);
    int rank = 0;
    for (int j = 0; j < 4; ++j) rank += tet[j] < tet[i];
    config.rank[i] = static_cast<std::uint8_t>(rank);
  }
  for (int k = 0; k < 6; ++k) {
    edge_numbers[k] = -1;
    if (!config.straddles(k)) continue;
    const VertId a = tet[kTetEdges[k][0]], b = tet[kTetEdges[k][1]];
    EdgeInfo& e = edge(a, b);
    if (covered(e, a, b)) config.covered |= static_cast<std::uint8_t>(1u << k);
    edge_numbers[k] = e.number;
  }
  return config;
}

bool CutClassifier::section_ends(const std::array<VertId, 3>& face, SectionEnd& p, SectionEnd& q) const {
  std::array<VertexState, 3> st;
  bool neg = false, pos = false;
  for (int i = 0; i < 3; ++i) {
    st[i] = state(face[i]);
    neg |= st[i] == VertexState::kNeg;
    pos |= st[i] == VertexState::kPos;
  }
  if (!(neg && pos)) return false;
  std::array<SectionEnd, 2> ends;
  int n = 0;
  for (int i = 0; i < 3 && n < 2; ++i) {
    if (is_on(st[i])) {
      std::array<double, 3> w{0, 0, 0};
      w[i] = 1;
      ends[n++] = {positions_[face[i].index()], w, st[i] == VertexState::kOnActive};
    }
  }
  for (int i = 0; i < 3 && n < 2; ++i) {
    const int j = (i + 1) % 3;
    if (!is_strict(st[i]) || !is_strict(st[j]) || st[i] == st[j]) continue;
    const bool i_low = face[i] < face[j];
    const int lo = i_low ? i : j, hi = i_low ? j : i;
    const double t = crossing_parameter(face[i], face[j]);
    std::array<double, 3> w{0, 0, 0};
    w[lo] = 1 - t;
    w[hi] = t;
    const Vec3& plo = positions_[face[lo].index()];
    const Vec3& phi = positions_[face[hi].index()];
    ends[n++] = {plo + t * (phi - plo), w, crossing_covered(face[i], face[j])};
  }
  if (n != 2) return false;
  p = ends[0];
  q = ends[1];
  return true;
}

CutClassifier::FacePoint CutClassifier::face_point(const std::array<VertId, 3>& face) const {
  SectionEnd p, q;
  if (!section_ends(face, p, q)) throw std::logic_error("face_point: the face is not crossed by the cut");
  if (!p.active) std::swap(p, q);
  // Continuing a stroke, p may be the last cut's crack front behind the
  // junction: the crack goes on from it through the polygon.
  int edge = -1;
  const double exit = continuation_ ? polygon_.last_inside_parameter(p.position, q.position, &edge)
                                    : polygon_.exit_parameter(p.position, q.position);
  // On a stroke's leading edge, exactly where the outline leaves the face
  // (stroke_junction.h): the next step starts there.
  const double clamp = continuation_ && edge >= 0 && edge == continuation_->leading_edge ? ClassifierDef::kMinSnap
                                                                                          : face_clamp_;
  const double s = std::clamp(exit, clamp, 1 - clamp);
  FacePoint out;
  out.position = p.position + s * (q.position - p.position);
  for (int i = 0; i < 3; ++i) out.weights[i] = (1 - s) * p.weights[i] + s * q.weights[i];
  return out;
}

CutClassifier::FacePoint CutClassifier::face_node(const std::array<VertId, 3>& face) const {
  SectionEnd p, q;
  if (!section_ends(face, p, q)) throw std::logic_error("face_node: the face is not crossed by the cut");
  FacePoint out;
  out.position = 0.5 * (p.position + q.position);
  for (int i = 0; i < 3; ++i) out.weights[i] = 0.5 * (p.weights[i] + q.weights[i]);
  return out;
}

}  // namespace mtcut::cut
