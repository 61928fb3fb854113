#include "cut/mt/mt_pieces.h"

#include <algorithm>
#include <numeric>
#include <span>
#include <string>

#include "engine/union_find.h"

namespace mtcut::cut {
namespace {

using engine::UnionFind;
using engine::VertId;


// The pieces' union-find. Nodes: the MT's vertices (node v), then one per
// fragment (n_vertices + f). A finest tet joins its four vertices, and every
// live tet joins its birth with its death, the drain aside (a finest tet's
// birth being its vertices). Finest tets sharing a vertex are in one piece
// either way; on vertices, the sets fit in cache (the MT has a fifth as many
// vertices as tets), and one pass over the tet slots in order reads the
// arrays as they are stored, where the fragments' lists scatter the reads.
struct PieceSets {
  UnionFind sets;
  std::size_t n_vertices;
  std::int32_t vertex(VertId v) const { return static_cast<std::int32_t>(v.index()); }
  std::int32_t fragment(FragId f) const { return static_cast<std::int32_t>(n_vertices + f.index()); }
  // A live tet's node: its birth's, or its first vertex's for a finest tet.
  std::int32_t tet(const Mt& mt, TetId t) const {
    return mt.birth(t) == mt.root() ? vertex(mt.tet(t)[0]) : fragment(mt.birth(t));
  }
};

PieceSets join_pieces(const Mt& mt) {
  PieceSets pieces{UnionFind(mt.num_vertices() + mt.num_fragments()), mt.num_vertices()};
  UnionFind& sets = pieces.sets;
  const FragId root = mt.root(), drain = mt.drain();
  for (std::size_t i = 0; i < mt.num_tets(); ++i) {
    const TetId t(i);
    if (!mt.alive(t)) continue;
    const FragId birth = mt.birth(t), death = mt.death(t);
    std::int32_t node;
    if (birth == root) {
      const engine::Tet& tet = mt.tet(t);
      node = pieces.vertex(tet[0]);
      for (int k = 1; k < 4; ++k) sets.unite(node, pieces.vertex(tet[k]));
    } else {
      node = pieces.fragment(birth);
    }
    if (death != drain) sets.unite(node, pieces.fragment(death));
  }
  return pieces;
}

}  // namespace

MtPieces find_pieces(const Mt& mt) {
  PieceSets sets = join_pieces(mt);
  // Numbered in ascending order of the tet ids of the finest tets.
  MtPieces pieces;
  std::vector<std::int32_t> piece_of_root(sets.sets.size(), -1);
  for (std::size_t i = 0; i < mt.num_tets(); ++i) {
    const TetId t(i);
    if (!mt.alive(t) || mt.birth(t) != mt.root()) continue;
    const auto r = static_cast<std::size_t>(sets.sets.find(sets.tet(mt, t)));
    if (piece_of_root[r] < 0) {
      piece_of_root[r] = static_cast<std::int32_t>(pieces.count++);
      pieces.finest_tets.push_back(0);
    }
    ++pieces.finest_tets[static_cast<std::size_t>(piece_of_root[r])];
  }
  pieces.fragments.resize(pieces.count);
  pieces.fragment_piece.assign(mt.num_fragments(), -1);
  for (std::size_t f = 0; f < mt.num_fragments(); ++f) {
    if (FragId(f) == mt.root() || FragId(f) == mt.drain()) continue;
    const std::int32_t p = piece_of_root[static_cast<std::size_t>(sets.sets.find(sets.fragment(FragId(f))))];
    pieces.fragment_piece[f] = p;
    if (p >= 0) pieces.fragments[static_cast<std::size_t>(p)].emplace_back(f);
  }
  pieces.tet_piece.assign(mt.num_tets(), -1);
  for (std::size_t i = 0; i < mt.num_tets(); ++i)
    if (mt.alive(TetId(i)))
      pieces.tet_piece[i] = piece_of_root[static_cast<std::size_t>(sets.sets.find(sets.tet(mt, TetId(i))))];
  return pieces;
}

std::size_t count_pieces(const Mt& mt) {
  // The sets that hold a finest tet's vertex: a vertex only cuts and
  // retractions left unused is a set of its own, and so may be a fragment
  // a retraction emptied.
  PieceSets sets = join_pieces(mt);
  std::vector<std::uint8_t> counted(sets.sets.size(), 0);
  std::size_t count = 0;
  for (TetId t : mt.created(mt.root())) {
    std::uint8_t& seen = counted[static_cast<std::size_t>(sets.sets.find(sets.vertex(mt.tet(t)[0])))];
    count += seen == 0;
    seen = 1;
  }
  return count;
}

std::vector<double> piece_volumes(const Mt& mt, const MtPieces& pieces) {
  std::vector<double> volume(pieces.count, 0.0);
  for (TetId t : mt.created(mt.root())) {
    const std::int32_t p = pieces.tet_piece[t.index()];
    if (p >= 0) volume[static_cast<std::size_t>(p)] += mt.volume(t);
  }
  return volume;
}

engine::ValidationReport validate_pieces(const Mt& mt, const MtPieces& pieces) {
  engine::ValidationReport report;
  if (pieces.fragment_piece.size() != mt.num_fragments() || pieces.tet_piece.size() != mt.num_tets() ||
      pieces.fragments.size() != pieces.count || pieces.finest_tets.size() != pieces.count) {
    report.add("pieces: sized for another MT or another count");
    return report;
  }
  const auto in_range = [&](std::int32_t p) { return p >= 0 && static_cast<std::size_t>(p) < pieces.count; };
  std::vector<std::vector<FragId>> fragments(pieces.count);
  for (std::size_t f = 0; f < mt.num_fragments(); ++f) {
    const bool special = FragId(f) == mt.root() || FragId(f) == mt.drain();
    const std::int32_t p = pieces.fragment_piece[f];
    if (special) continue;
    if (!in_range(p))
      report.add("pieces: fragment " + std::to_string(f) + " is in no piece");
    else
      fragments[static_cast<std::size_t>(p)].emplace_back(f);
  }
  if (fragments != pieces.fragments) report.add("pieces: the pieces' fragment lists are not their fragments'");
  // Apart: no vertex is used by tets of two pieces, at any resolution (the
  // first such vertex is reported).
  std::vector<std::int32_t> vertex_piece(mt.num_vertices(), -1);
  std::vector<std::size_t> finest(pieces.count, 0);
  bool shared = false;
  for (std::size_t i = 0; i < mt.num_tets(); ++i) {
    const TetId t(i);
    if (!mt.alive(t)) continue;
    const std::int32_t p = pieces.tet_piece[i];
    if (!in_range(p)) {
      report.add("pieces: tet " + std::to_string(i) + " is in no piece");
      continue;
    }
    if (mt.birth(t) == mt.root()) ++finest[static_cast<std::size_t>(p)];
    for (FragId f : {mt.birth(t), mt.death(t)})
      if (f != mt.root() && f != mt.drain() && pieces.fragment_piece[f.index()] != p)
        report.add("pieces: tet " + std::to_string(i) + " joins pieces " + std::to_string(p) + " and " +
                   std::to_string(pieces.fragment_piece[f.index()]));
    for (VertId v : mt.tet(t)) {
      std::int32_t& owner = vertex_piece[v.index()];
      if (owner < 0) owner = p;
      if (owner != p && !shared) {
        report.add("pieces: vertex " + std::to_string(v.value) + " is in pieces " + std::to_string(owner) + " and " +
                   std::to_string(p));
        shared = true;
      }
    }
  }
  if (finest != pieces.finest_tets) report.add("pieces: the finest tets counted per piece differ");
  return report;
}

Mt extract_piece_mt(const Mt& mt, const MtPieces& pieces, std::size_t piece, std::vector<VertId>* vertex_ids) {
  const auto p = static_cast<std::int32_t>(piece);
  std::vector<TetId> fine, rest;
  std::vector<std::int32_t> local(mt.num_vertices(), -1);
  std::vector<VertId> ids;
  for (std::size_t i = 0; i < mt.num_tets(); ++i) {
    const TetId t(i);
    if (!mt.alive(t) || pieces.tet_piece[i] != p) continue;
    (mt.birth(t) == mt.root() ? fine : rest).push_back(t);
    for (VertId v : mt.tet(t))
      if (local[v.index()] < 0) {
        local[v.index()] = 0;
        ids.push_back(v);
      }
  }
  std::sort(ids.begin(), ids.end());
  for (std::size_t i = 0; i < ids.size(); ++i) local[ids[i].index()] = static_cast<std::int32_t>(i);
  const auto renumber = [&](TetId t) {
    engine::Tet tet = mt.tet(t);
    for (VertId& v : tet) v = VertId(local[v.index()]);
    return tet;
  };

  engine::TetMesh mesh;
  for (VertId v : ids) mesh.positions.push_back(mt.position(v));
  for (TetId t : fine) mesh.tets.push_back(renumber(t));
  Mt out = Mt::from_fine_mesh(mesh);
  out.set_boundary_preserved(mt.boundary_preserved());
  std::vector<FragId> frag_map(mt.num_fragments());
  frag_map[mt.root().index()] = out.root();
  for (FragId f : pieces.fragments[piece]) frag_map[f.index()] = out.add_fragment();
  const FragId drain = out.add_fragment();
  out.set_drain(drain);
  frag_map[mt.drain().index()] = drain;
  for (std::size_t i = 0; i < fine.size(); ++i) {
    out.set_boundary_mask(TetId(i), mt.boundary_mask(fine[i]));
    out.set_death(TetId(i), frag_map[mt.death(fine[i]).index()]);
  }
  for (TetId t : rest)
    out.add_copy(mt, t, renumber(t), frag_map[mt.birth(t).index()], frag_map[mt.death(t).index()]);
  if (vertex_ids) *vertex_ids = std::move(ids);
  return out;
}

}  // namespace mtcut::cut
