#include "cut/mesh_cutter.h"

#include <algorithm>
#include <chrono>
#include <unordered_map>
#include <memory>
#include <numeric>
#include <stdexcept>

#include "cut/tet_splitter.h"
#include "cut/vertex_unpinch.h"
#include "engine/stopwatch.h"
#include "engine/tet_adjacency.h"
#include "engine/tet_components.h"
#include "engine/tet_geometry.h"

namespace mtcut::cut {
namespace {

using Clock = std::chrono::steady_clock;
using engine::Tet;
using engine::TetMesh;

}  // namespace

std::size_t count_pieces(const TetMesh& mesh) { return engine::tet_components(mesh.tets, mesh.num_vertices()).count(); }

namespace {

// One attempt: `vetoes` are kept off the cut from the start.
MeshCutResult cut_once(TetMesh& mesh, const CutPolygon& polygon, const CutterDef& def, SplitTable& recipes,
                       const std::vector<VertId>& initial_vetoes, std::vector<std::uint32_t>& nearby) {
  const auto start = Clock::now();
  MeshCutResult result;
  CutStats& stats = result.stats;
  const std::size_t n_tets = mesh.num_tets();

  // Tets whose box comes within the classifier's margin of the polygon's box
  // (a vertex that far off the polygon may still be split).
  double longest = 0;
  for (const Tet& tet : mesh.tets)
    for (const auto& e : engine::kTetEdges)
      longest = std::max(longest, (mesh.position(tet[e[0]]) - mesh.position(tet[e[1]])).squaredNorm());
  ClassifierDef cdef;
  cdef.snap = def.snap;
  const double margin = ClassifierDef::margin_fraction(def.snap) * std::sqrt(longest) * 1.01;
  const Vec3 box_min = polygon.box_min() - Vec3::Constant(margin);
  const Vec3 box_max = polygon.box_max() + Vec3::Constant(margin);

  std::vector<std::uint32_t> candidates;
  std::vector<std::uint8_t> is_candidate(n_tets, 0);
  for (std::size_t t = 0; t < n_tets; ++t) {
    const Tet& tet = mesh.tets[t];
    Vec3 lo = mesh.position(tet[0]), hi = lo;
    for (int i = 1; i < 4; ++i) {
      lo = lo.cwiseMin(mesh.position(tet[i]));
      hi = hi.cwiseMax(mesh.position(tet[i]));
    }
    if ((lo.array() > box_max.array()).any() || (hi.array() < box_min.array()).any()) continue;
    candidates.push_back(static_cast<std::uint32_t>(t));
  }
  // Every tet the cut may touch: the later passes look only at these (and
  // at the tets appended by the split).
  nearby = candidates;
  const auto split_start = Clock::now();
  // Classify; where splitting the vertices on the cut would pinch the mesh,
  // pull vertices onto the cut or keep them off it, and classify again (both
  // sets only grow).
  std::vector<VertId> vetoes = initial_vetoes, pulls;
  std::unique_ptr<CutClassifier> classifier;
  for (int round = 0;; ++round) {
    classifier = std::make_unique<CutClassifier>(polygon, mesh.positions, cdef);
    for (VertId v : vetoes) classifier->veto(v);
    for (VertId v : pulls) classifier->pull_in(v);
    for (std::uint32_t t : candidates) classifier->add_candidate(mesh.tets[t]);
    classifier->finalize();
    const PinchFix fix = find_pinches(mesh, *classifier, nearby);
    if (fix.empty() || round == 12) break;
    // Pulling in first; once a round has to veto, keep vetoing.
    vetoes.insert(vetoes.end(), fix.veto.begin(), fix.veto.end());
    pulls.insert(pulls.end(), fix.pull_in.begin(), fix.pull_in.end());
    stats.vetoed_vertices += fix.veto.size();
    stats.pulled_vertices += fix.pull_in.size();
  }
  CutClassifier& cls = *classifier;
  {
    std::size_t kept = 0;
    for (std::uint32_t t : candidates) {
      const Tet& tet = mesh.tets[t];
      bool one_side = true;
      for (int i = 1; i < 4; ++i) one_side &= cls.state(tet[i]) == cls.state(tet[0]) && is_strict(cls.state(tet[0]));
      if (one_side) continue;
      candidates[kept++] = t;
      is_candidate[t] = 1;
    }
    candidates.resize(kept);
  }
  stats.candidate_tets = candidates.size();

  std::vector<std::uint8_t> split_vertex(mesh.num_vertices(), 0);
  for (VertId v : cls.on_vertices()) {
    if (cls.state(v) == VertexState::kOnActive) split_vertex[v.index()] = 1;
    if (cls.snapped(v)) result.snapped_vertices.push_back(v);
  }
  stats.snapped_vertices = result.snapped_vertices.size();
  result.resided_vertices = cls.resided_vertices();

  VertexFactory factory(mesh.num_vertices());
  std::vector<double> parent_quality;  // (split tets) smallest dihedral angle
  std::vector<Tet> made;
  std::vector<std::uint32_t> made_first;
  auto relabel = [&](std::size_t t) {
    Tet& tet = mesh.tets[t];
    if (std::none_of(tet.begin(), tet.end(), [&](VertId v) { return split_vertex[v.index()] != 0; })) return;
    if (cls.side_of_uncut(tet) == VertexState::kPos) return;  // the positive side keeps the vertex
    for (VertId& v : tet) {
      if (!split_vertex[v.index()]) continue;
      PointKey key;
      key.kind = PointKind::kVertexCopy;
      key.side = -1;
      key.ids[0] = v.value;
      const VertId original = v;
      v = factory.get(key, [&] { return MadeVertex::at_vertex(original, mesh.positions[original.index()]); });
    }
    result.relabeled_tets.push_back(TetId(t));
  };

  for (std::uint32_t t : candidates) {
    const Tet tet = mesh.tets[t];
    const TetConfig config = cls.configure(tet);
    if (!config.is_cut()) {
      relabel(t);
      continue;
    }
    made_first.push_back(static_cast<std::uint32_t>(made.size()));
    const auto corners = mesh.corners(TetId(static_cast<std::size_t>(t)));
    parent_quality.push_back(engine::min_dihedral_deg(corners[0], corners[1], corners[2], corners[3]));
    const CutCase kind = split_tet(tet, config, cls, recipes, factory, made);
    ++stats.per_case[static_cast<std::size_t>(kind)];
    result.split_tets.push_back(TetId(static_cast<std::size_t>(t)));
  }
  for (std::uint32_t t : nearby)
    if (!is_candidate[t]) relabel(t);
  made_first.push_back(static_cast<std::uint32_t>(made.size()));

  // Apply: new vertices, then each split tet's slot and the appended rest.
  factory.apply(mesh);
  result.split_first.push_back(0);
  for (std::size_t i = 0; i < result.split_tets.size(); ++i) {
    const TetId old = result.split_tets[i];
    for (std::uint32_t j = made_first[i]; j < made_first[i + 1]; ++j) {
      TetId id = old;
      if (j == made_first[i]) {
        mesh.tets[old.index()] = made[j];
      } else {
        id = TetId(mesh.tets.size());
        mesh.tets.push_back(made[j]);
      }
      result.replacements.push_back(id);
    }
    result.split_first.push_back(static_cast<std::uint32_t>(result.replacements.size()));
  }
  result.new_vertices = factory.made();

  // Vertices the cut went through: their stars must not be pinched.
  std::vector<VertId> through;
  for (VertId v : cls.on_vertices()) through.push_back(v);
  for (const MadeVertex& v : result.new_vertices)
    if (v.key.kind == PointKind::kVertexCopy) through.push_back(v.id);
  for (std::size_t t = n_tets; t < mesh.num_tets(); ++t) nearby.push_back(static_cast<std::uint32_t>(t));
  stats.unpinched_vertices = unpinch_vertices(mesh, through, nearby, result.new_vertices, result.relabeled_tets);
  stats.split_seconds = engine::seconds_since(split_start);

  stats.split_tets = result.split_tets.size();
  stats.new_tets = made.size();
  stats.relabeled_tets = result.relabeled_tets.size();
  stats.new_vertices = result.new_vertices.size();
  stats.split_vertices = static_cast<std::size_t>(std::count_if(
      result.new_vertices.begin(), result.new_vertices.end(),
      [](const MadeVertex& v) { return v.key.kind == PointKind::kVertexCopy; }));
  for (std::size_t i = 0; i < result.split_tets.size(); ++i) {
    double worst = 180;
    for (std::uint32_t j = result.split_first[i]; j < result.split_first[i + 1]; ++j) {
      const auto c = mesh.corners(result.replacements[j]);
      worst = std::min(worst, engine::min_dihedral_deg(c[0], c[1], c[2], c[3]));
    }
    stats.min_dihedral_deg = std::min(stats.min_dihedral_deg, worst);
    if (parent_quality[i] > 0) stats.min_dihedral_ratio = std::min(stats.min_dihedral_ratio, worst / parent_quality[i]);
  }
  stats.seconds = engine::seconds_since(start);
  return result;
}

// Edges of the cut mesh that are not manifold (more than one face each way
// on the boundary), among edges with an end the cut made or went through.
// Returns the vertices the cut went through around them.
std::vector<VertId> find_torn_edges(const TetMesh& mesh, const MeshCutResult& r, std::size_t first_new) {
  std::vector<std::uint8_t> affected(mesh.num_vertices(), 0);
  for (std::size_t v = first_new; v < mesh.num_vertices(); ++v) affected[v] = 1;
  for (VertId v : r.snapped_vertices) affected[v.index()] = 1;
  for (const auto* list : {&r.replacements, &r.relabeled_tets})
    for (TetId t : *list)
      for (VertId v : mesh.tets[t.index()]) affected[v.index()] = 1;
  // All tets holding an affected vertex (some of an old vertex's tets may
  // lie away from the polygon).
  std::vector<std::uint32_t> near;
  for (std::size_t t = 0; t < mesh.num_tets(); ++t)
    for (VertId v : mesh.tets[t])
      if (affected[v.index()]) {
        near.push_back(static_cast<std::uint32_t>(t));
        break;
      }
  // Faces holding an affected vertex appear only in `near` tets.
  std::unordered_map<std::uint64_t, int> faces;  // sorted face -> uses
  auto face_key = [](std::array<std::int32_t, 3> f) {
    std::sort(f.begin(), f.end());
    return static_cast<std::uint64_t>(f[0]) << 42 ^ static_cast<std::uint64_t>(f[1]) << 21 ^ static_cast<std::uint64_t>(f[2]);
  };
  for (std::uint32_t t : near)
    for (const auto& lf : engine::kTetFaces) {
      const auto& tet = mesh.tets[t];
      ++faces[face_key({tet[lf[0]].value, tet[lf[1]].value, tet[lf[2]].value})];
    }
  std::unordered_map<std::uint64_t, int> directed;  // boundary edge a -> b count
  for (std::uint32_t t : near)
    for (const auto& lf : engine::kTetFaces) {
      const auto& tet = mesh.tets[t];
      const std::array<VertId, 3> f = {tet[lf[0]], tet[lf[1]], tet[lf[2]]};
      if (faces[face_key({f[0].value, f[1].value, f[2].value})] != 1) continue;
      for (int k = 0; k < 3; ++k) {
        const VertId a = f[k], b = f[(k + 1) % 3];
        if (!affected[a.index()] && !affected[b.index()]) continue;
        ++directed[static_cast<std::uint64_t>(a.value) << 32 | static_cast<std::uint32_t>(b.value)];
      }
    }
  std::vector<VertId> out;
  for (const auto& [key, n] : directed) {
    const auto a = static_cast<std::int32_t>(key >> 32), b = static_cast<std::int32_t>(key & 0xffffffffu);
    const auto back = directed.find(static_cast<std::uint64_t>(b) << 32 | static_cast<std::uint32_t>(a));
    if (n == 1 && back != directed.end() && back->second == 1) continue;
    // Keep the vertices the cut went through around this edge off the cut.
    for (std::uint32_t t : near) {
      const auto& tet = mesh.tets[t];
      if (std::find(tet.begin(), tet.end(), VertId(a)) == tet.end() ||
          std::find(tet.begin(), tet.end(), VertId(b)) == tet.end())
        continue;
      for (VertId v : tet) {
        // A copy made by this cut stands for the vertex it copies.
        VertId original = v;
        if (v.index() >= first_new) {
          const MadeVertex& nv = r.new_vertices[v.index() - first_new];
          if (nv.key.kind != PointKind::kVertexCopy) continue;
          original = VertId(nv.key.ids[0]);
          while (original.index() >= first_new) original = VertId(r.new_vertices[original.index() - first_new].key.ids[0]);
        }
        if (std::find(r.snapped_vertices.begin(), r.snapped_vertices.end(), original) != r.snapped_vertices.end() ||
            std::any_of(r.new_vertices.begin(), r.new_vertices.end(), [&](const MadeVertex& nv) {
              return nv.key.kind == PointKind::kVertexCopy && nv.key.ids[0] == original.value;
            }))
          out.push_back(original);
      }
    }
  }
  return out;
}

}  // namespace

MeshCutResult cut_mesh(TetMesh& mesh, const CutPolygon& polygon, const CutterDef& def, SplitTable* table) {
  const auto start = Clock::now();
  SplitTable local(def.scheme);
  SplitTable& recipes = table ? *table : local;
  if (recipes.scheme() != def.scheme) throw std::invalid_argument("cut_mesh: the split table is for another scheme");
  // Where the result tears (an edge left with two wedges on one side, which
  // the pinch guard did not foresee), undo and cut again keeping the vertices
  // the cut went through there off it.
  const std::vector<engine::Tet> tets_before = mesh.tets;
  const std::size_t vertices_before = mesh.num_vertices();
  std::vector<VertId> vetoes;
  for (int attempt = 0;; ++attempt) {
    std::vector<std::uint32_t> nearby;
    MeshCutResult result = cut_once(mesh, polygon, def, recipes, vetoes, nearby);
    const std::vector<VertId> torn =
        attempt < 4 ? find_torn_edges(mesh, result, vertices_before) : std::vector<VertId>{};
    if (torn.empty()) {
      result.stats.vetoed_vertices += vetoes.size();
      result.stats.seconds = engine::seconds_since(start);
      if (def.count_pieces) result.stats.pieces = count_pieces(mesh);
      return result;
    }
    vetoes.insert(vetoes.end(), torn.begin(), torn.end());
    mesh.tets = tets_before;
    mesh.positions.resize(vertices_before);
  }
}

}  // namespace mtcut::cut
