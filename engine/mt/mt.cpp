#include "engine/mt/mt.h"

#include <algorithm>
#include <atomic>
#include <cassert>

#include "engine/mt/tet_error.h"
#include "engine/radix_sort.h"
#include "engine/reserve_geometric.h"
#include "engine/tet_adjacency.h"
#include "engine/tet_geometry.h"

namespace mtcut::engine {
namespace {

template <class T>
std::size_t vector_bytes(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}

std::vector<FragId> sorted_unique(std::vector<FragId> ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

}  // namespace

std::uint64_t Mt::InstanceId::next() {
  static std::atomic<std::uint64_t> next_value{1};
  return next_value.fetch_add(1, std::memory_order_relaxed);
}

Mt Mt::from_fine_mesh(const TetMesh& fine) {
  Mt mt;
  mt.positions_ = fine.positions;
  mt.root_ = mt.add_fragment();
  const TetAdjacency adjacency = build_adjacency(fine);
  const std::size_t n = fine.num_tets();
  mt.tet_verts_.reserve(n);
  for (std::size_t t = 0; t < n; ++t) {
    FaceMask mask = 0;
    for (int f = 0; f < 4; ++f)
      if (!adjacency.neighbors[t][f].valid()) mask |= static_cast<FaceMask>(1u << f);
    mt.add_tet(fine.tets[t], mt.root_, FragId(), mask);
  }
  mt.fine_volume_ = fine.total_volume();
  return mt;
}

VertId Mt::add_vertex(const Vec3& rest_position) {
  positions_.push_back(rest_position);
  ++revision_;
  return VertId(positions_.size() - 1);
}

void Mt::reserve(std::size_t vertices, std::size_t tets) {
  // Geometric growth: a cut reserves what it adds (reserve_geometric.h).
  const auto grow = [](auto& v, std::size_t n) { reserve_geometric(v, n); };
  grow(positions_, vertices);
  grow(tet_verts_, tets);
  grow(tet_birth_, tets);
  grow(tet_death_, tets);
  grow(tet_error_, tets);
  grow(tet_error_inherited_, tets);
  grow(tet_boundary_, tets);
  grow(tet_birth_slot_, tets);
  grow(tet_death_slot_, tets);
}

std::array<Vec3, 4> Mt::corners(TetId t) const {
  const Tet& v = tet(t);
  return {position(v[0]), position(v[1]), position(v[2]), position(v[3])};
}

double Mt::volume(TetId t) const {
  const auto c = corners(t);
  return signed_volume(c[0], c[1], c[2], c[3]);
}

TetId Mt::add_tet(const Tet& verts, FragId birth, FragId death, FaceMask boundary) {
  const Vec3 &a = position(verts[0]), &b = position(verts[1]), &c = position(verts[2]), &d = position(verts[3]);
  return append_tet(verts, birth, death, boundary, tet_error(a, b, c, d), false);
}

TetId Mt::add_piece(const Tet& verts, TetId whole, FaceMask boundary) {
  return add_pieces(std::span<const Tet>(&verts, 1), whole, std::span<const FaceMask>(&boundary, 1));
}

TetId Mt::add_pieces(std::span<const Tet> verts, TetId whole, std::span<const FaceMask> boundary) {
  assert(alive(whole) && boundary.size() == verts.size());
  const FragId birth = tet_birth_[whole.index()], death = tet_death_[whole.index()];
  const float error = tet_error_[whole.index()];
  const std::size_t first = tet_verts_.size(), n = verts.size();
  tet_verts_.insert(tet_verts_.end(), verts.begin(), verts.end());
  tet_error_.resize(first + n, error);
  tet_error_inherited_.resize(first + n, 1);
  tet_boundary_.insert(tet_boundary_.end(), boundary.begin(), boundary.end());
  const auto append_to = [&](std::vector<TetId>& list, std::vector<std::int32_t>& slots) {
    for (std::size_t i = 0; i < n; ++i) {
      slots.push_back(static_cast<std::int32_t>(list.size()));
      list.emplace_back(first + i);
    }
  };
  tet_birth_.resize(first + n, birth);
  append_to(frag_created_[birth.index()], tet_birth_slot_);
  tet_death_.resize(first + n, death);
  if (death.valid())
    append_to(frag_replaced_[death.index()], tet_death_slot_);
  else
    tet_death_slot_.resize(first + n, -1);
  live_tets_ += n;
  ++revision_;
  frag_created_revision_[birth.index()] = revision_;
  return TetId(first);
}

TetId Mt::add_copy(const Mt& source, TetId t, const Tet& verts, FragId birth, FragId death) {
  return append_tet(verts, birth, death, source.boundary_mask(t), source.error(t), source.error_inherited(t));
}

TetId Mt::append_tet(const Tet& verts, FragId birth, FragId death, FaceMask boundary, float error, bool inherited) {
  assert(birth.valid() && birth.index() < num_fragments());
  const TetId t(tet_verts_.size());
  tet_verts_.push_back(verts);
  tet_error_.push_back(error);
  tet_error_inherited_.push_back(inherited ? 1 : 0);
  tet_boundary_.push_back(boundary);
  tet_birth_.push_back(birth);
  tet_birth_slot_.push_back(static_cast<std::int32_t>(frag_created_[birth.index()].size()));
  frag_created_[birth.index()].push_back(t);
  tet_death_.push_back(FragId());
  tet_death_slot_.push_back(-1);
  if (death.valid()) set_death(t, death);
  ++live_tets_;
  ++revision_;
  structure_revision_ = revision_;
  frag_created_revision_[birth.index()] = revision_;
  return t;
}

void Mt::erase_from(std::vector<std::vector<TetId>>& lists, std::vector<std::int32_t>& slots, FragId f, TetId t) {
  auto& list = lists[f.index()];
  const std::int32_t at = slots[t.index()];
  assert(at >= 0 && list[static_cast<std::size_t>(at)] == t);
  const TetId last = list.back();
  list[static_cast<std::size_t>(at)] = last;
  slots[last.index()] = at;
  list.pop_back();
  slots[t.index()] = -1;
}

void Mt::kill_tet(TetId t) {
  assert(alive(t));
  erase_from(frag_created_, tet_birth_slot_, birth(t), t);
  if (death(t).valid()) erase_from(frag_replaced_, tet_death_slot_, death(t), t);
  ++revision_;
  frag_created_revision_[birth(t).index()] = revision_;
  tet_birth_[t.index()] = FragId();
  tet_death_[t.index()] = FragId();
  --live_tets_;
}

void Mt::revive_tet(TetId t, FragId birth, FragId death) {
  assert(!alive(t) && birth.valid() && birth.index() < num_fragments());
  tet_birth_[t.index()] = birth;
  tet_birth_slot_[t.index()] = static_cast<std::int32_t>(frag_created_[birth.index()].size());
  frag_created_[birth.index()].push_back(t);
  tet_death_[t.index()] = FragId();
  tet_death_slot_[t.index()] = -1;
  ++live_tets_;
  ++revision_;
  frag_created_revision_[birth.index()] = revision_;
  if (death.valid()) link_death(t, death);
}

void Mt::set_birth(TetId t, FragId f) {
  assert(alive(t) && f.valid());
  erase_from(frag_created_, tet_birth_slot_, birth(t), t);
  ++revision_;
  structure_revision_ = revision_;
  frag_created_revision_[birth(t).index()] = revision_;
  frag_created_revision_[f.index()] = revision_;
  tet_birth_[t.index()] = f;
  tet_birth_slot_[t.index()] = static_cast<std::int32_t>(frag_created_[f.index()].size());
  frag_created_[f.index()].push_back(t);
}

void Mt::set_death(TetId t, FragId f) {
  link_death(t, f);
  structure_revision_ = revision_;
}

void Mt::link_death(TetId t, FragId f) {
  assert(alive(t));
  if (death(t).valid()) erase_from(frag_replaced_, tet_death_slot_, death(t), t);
  tet_death_[t.index()] = f;
  if (f.valid()) {
    tet_death_slot_[t.index()] = static_cast<std::int32_t>(frag_replaced_[f.index()].size());
    frag_replaced_[f.index()].push_back(t);
  }
  ++revision_;
}

void Mt::move_groups(FragId f, std::span<const FragId> parts, std::span<const std::int32_t> group) {
  assert(!parts.empty() && parts[0] == f);
  assert(group.size() == created(f).size() + replaced(f).size());
  const auto move = [&](std::vector<std::vector<TetId>>& lists, std::vector<FragId>& of,
                        std::vector<std::int32_t>& slots, std::span<const std::int32_t> to) {
    std::vector<TetId>& list = lists[f.index()];  // the parts' lists are others: pushes leave it be
    std::size_t kept = 0;
    for (std::size_t i = 0; i < list.size(); ++i) {
      const TetId t = list[i];
      const auto g = static_cast<std::size_t>(to[i]);
      std::vector<TetId>& into = g == 0 ? list : lists[parts[g].index()];
      const std::size_t at = g == 0 ? kept++ : into.size();
      if (g == 0) {
        list[at] = t;
      } else {
        into.push_back(t);
        of[t.index()] = parts[g];
      }
      slots[t.index()] = static_cast<std::int32_t>(at);
    }
    list.resize(kept);
  };
  const std::size_t n_created = created(f).size();
  move(frag_created_, tet_birth_, tet_birth_slot_, group.first(n_created));
  move(frag_replaced_, tet_death_, tet_death_slot_, group.subspan(n_created));
  ++revision_;
  structure_revision_ = revision_;
  for (FragId p : parts) frag_created_revision_[p.index()] = revision_;
}

void Mt::reserve_fragment(FragId f, std::size_t created, std::size_t replaced) {
  frag_created_[f.index()].reserve(created);
  frag_replaced_[f.index()].reserve(replaced);
}

float Mt::fragment_error(FragId f) const {
  float e = 0.0f;
  for (TetId t : created(f)) e = std::max(e, error(t));
  return e;
}

FragId Mt::add_fragment() {
  frag_created_.emplace_back();
  frag_replaced_.emplace_back();
  ++revision_;
  structure_revision_ = revision_;
  frag_created_revision_.push_back(revision_);
  return FragId(frag_created_.size() - 1);
}

void Mt::remove_last_fragment() {
  assert(num_fragments() > 1 && frag_created_.back().empty() && frag_replaced_.back().empty());
  assert(FragId(num_fragments() - 1) != root_ && FragId(num_fragments() - 1) != drain_);
  frag_created_.pop_back();
  frag_replaced_.pop_back();
  frag_created_revision_.pop_back();
  ++revision_;
  structure_revision_ = revision_;
}

std::size_t Mt::num_unused_vertices() const {
  std::vector<std::uint8_t> used(num_vertices(), 0);
  for (std::size_t t = 0; t < num_tets(); ++t)
    if (alive(TetId(t)))
      for (VertId v : tet_verts_[t]) used[v.index()] = 1;
  return static_cast<std::size_t>(std::count(used.begin(), used.end(), std::uint8_t{0}));
}

Mt::Compaction Mt::compact(std::size_t first_droppable_vertex, std::span<const TetId> keep_dead) {
  Compaction out;
  // tet_map: 0 kept, -1 dropped, until numbered below.
  out.tet_map.assign(num_tets(), -1);
  for (std::size_t t = 0; t < num_tets(); ++t)
    if (alive(TetId(t))) out.tet_map[t] = 0;
  for (TetId t : keep_dead) out.tet_map[t.index()] = 0;
  out.vertex_map.assign(num_vertices(), -1);
  for (std::size_t v = 0; v < std::min(first_droppable_vertex, num_vertices()); ++v) out.vertex_map[v] = 0;
  for (std::size_t t = 0; t < num_tets(); ++t)
    if (out.tet_map[t] == 0)
      for (VertId v : tet_verts_[t]) out.vertex_map[v.index()] = 0;
  std::int32_t next = 0;
  for (std::size_t v = 0; v < num_vertices(); ++v) {
    if (out.vertex_map[v] < 0) continue;
    out.vertex_map[v] = next;
    positions_[static_cast<std::size_t>(next++)] = positions_[v];
  }
  out.vertices_dropped = num_vertices() - static_cast<std::size_t>(next);
  positions_.resize(static_cast<std::size_t>(next));

  std::size_t kept = 0;
  for (std::size_t t = 0; t < num_tets(); ++t) {
    if (out.tet_map[t] < 0) continue;
    out.tet_map[t] = static_cast<std::int32_t>(kept);
    Tet verts = tet_verts_[t];
    for (VertId& v : verts) v = out.vertex(v);
    tet_verts_[kept] = verts;
    tet_birth_[kept] = tet_birth_[t];
    tet_death_[kept] = tet_death_[t];
    tet_error_[kept] = tet_error_[t];
    tet_error_inherited_[kept] = tet_error_inherited_[t];
    tet_boundary_[kept] = tet_boundary_[t];
    tet_birth_slot_[kept] = tet_birth_slot_[t];
    tet_death_slot_[kept] = tet_death_slot_[t];
    ++kept;
  }
  out.tets_dropped = num_tets() - kept;
  // The arrays keep their capacity: the stroke in progress grows them
  // again, and growing them back would copy them all in one of its steps.
  const auto shrink = [kept](auto& v) { v.resize(kept); };
  shrink(tet_verts_);
  shrink(tet_birth_);
  shrink(tet_death_);
  shrink(tet_error_);
  shrink(tet_error_inherited_);
  shrink(tet_boundary_);
  shrink(tet_birth_slot_);
  shrink(tet_death_slot_);
  // The lists hold live tets only, in place: each keeps its order, so every
  // tet's slot in them stays.
  for (auto* lists : {&frag_created_, &frag_replaced_})
    for (std::vector<TetId>& list : *lists)
      for (TetId& t : list) t = out.tet(t);
  ++revision_;
  structure_revision_ = revision_;
  std::fill(frag_created_revision_.begin(), frag_created_revision_.end(), revision_);
  instance_ = InstanceId{};
  return out;
}

std::vector<FragId> Mt::parents(FragId f) const {
  std::vector<FragId> out;
  out.reserve(replaced(f).size());
  for (TetId t : replaced(f)) out.push_back(birth(t));
  return sorted_unique(std::move(out));
}

std::vector<FragId> Mt::children(FragId f) const {
  std::vector<FragId> out;
  out.reserve(created(f).size());
  for (TetId t : created(f))
    if (death(t).valid()) out.push_back(death(t));
  return sorted_unique(std::move(out));
}

std::vector<FragId> Mt::topological_order() const {
  const std::size_t n = num_fragments();
  // In-degree counts arcs (one per replaced tet), so no deduplication is needed.
  std::vector<std::int32_t> pending(n, 0);
  for (std::size_t f = 0; f < n; ++f) pending[f] = static_cast<std::int32_t>(frag_replaced_[f].size());
  std::vector<FragId> order;
  order.reserve(n);
  if (!root_.valid() || pending[root_.index()] != 0) return order;
  order.push_back(root_);
  for (std::size_t head = 0; head < order.size(); ++head) {
    for (TetId t : created(order[head])) {
      const FragId c = death(t);
      if (c.valid() && --pending[c.index()] == 0) order.push_back(c);
    }
  }
  return order;
}

std::size_t Mt::bytes() const {
  std::size_t total = vector_bytes(positions_) + vector_bytes(tet_verts_) + vector_bytes(tet_birth_) +
                      vector_bytes(tet_death_) + vector_bytes(tet_error_) + vector_bytes(tet_error_inherited_) +
                      vector_bytes(tet_boundary_) +
                      vector_bytes(tet_birth_slot_) + vector_bytes(tet_death_slot_) + vector_bytes(frag_created_) +
                      vector_bytes(frag_replaced_) + vector_bytes(frag_created_revision_);
  for (const auto& list : frag_created_) total += vector_bytes(list);
  for (const auto& list : frag_replaced_) total += vector_bytes(list);
  return total;
}

std::vector<OrientedFace> outer_faces(const Mt& mt, std::span<const TetId> tets) {
  // Each face as its ids ascending and where it is (4 list position + local
  // face), in two words: sorted by them, the copies of a face become
  // neighbours. A radix sort's passes cost 256 counters each whatever the
  // size, so a fragment's few faces (validate_fragment asks for every
  // fragment's) are compared instead.
  assert(tets.size() < (std::size_t{1} << 30));
  using FaceKey = std::array<std::uint64_t, 2>;
  std::vector<FaceKey> keys;
  keys.reserve(4 * tets.size());
  for (std::size_t i = 0; i < tets.size(); ++i) {
    const Tet& v = mt.tet(tets[i]);
    for (int f = 0; f < 4; ++f) {
      const auto ids = sorted_face_ids(face_vertices(v, f));
      keys.push_back({std::uint64_t{ids[0]} << 32 | ids[1], std::uint64_t{ids[2]} << 32 | (4 * i + f)});
    }
  }
  constexpr std::size_t kRadixMin = 1024;
  if (keys.size() < kRadixMin) {
    std::sort(keys.begin(), keys.end());
  } else {
    std::vector<FaceKey> scratch;
    radix_sort<2>(keys, scratch, [](const FaceKey& k) { return k; });
  }
  const auto same_face = [](const FaceKey& a, const FaceKey& b) { return a[0] == b[0] && a[1] >> 32 == b[1] >> 32; };
  std::vector<OrientedFace> outer;
  for (std::size_t i = 0; i < keys.size();) {
    std::size_t j = i + 1;
    while (j < keys.size() && same_face(keys[j], keys[i])) ++j;
    if (j - i == 1) {
      const auto at = static_cast<std::uint32_t>(keys[i][1]);
      OrientedFace face;
      face.tet = tets[at / 4];
      face.local_face = static_cast<int>(at % 4);
      face.verts = face_vertices(mt.tet(face.tet), face.local_face);
      face.sorted = {VertId(static_cast<std::int32_t>(keys[i][0] >> 32)),
                     VertId(static_cast<std::int32_t>(static_cast<std::uint32_t>(keys[i][0]))),
                     VertId(static_cast<std::int32_t>(keys[i][1] >> 32))};
      outer.push_back(face);
    }
    i = j;
  }
  return outer;
}

}  // namespace mtcut::engine
