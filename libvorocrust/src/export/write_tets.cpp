// The dual tetrahedral mesh of a clipped Voronoi mesh (Yan et al. 2011, 5.2) as tets.vtu.
#include <cstdint>
#include <vector>

#include "clipping/dual_tets.hpp"
#include "export/vtu_arrays.hpp"
#include "vorocrust/write_vtu.hpp"

namespace vorocrust {

void write_tets_vtu(const VoronoiMesh& mesh, const std::filesystem::path& path) {
  constexpr std::uint8_t kTetra = 10;
  const clipping::DualTets dual = clipping::dual_tets(mesh);
  const std::size_t tets = dual.tets.size();
  const std::size_t sites = mesh.cells.size();
  std::vector<clipping::TetShape> shapes(tets);
  for (std::size_t t = 0; t < tets; ++t) {
    const auto site = [&](int k) -> const Point& { return mesh.cells[dual.tets[t][k]].site; };
    shapes[t] = clipping::tet_shape(site(0), site(1), site(2), site(3));
  }
  using S = vtu::Section;
  using vtu::put;
  const auto shape = [&](double clipping::TetShape::*measure) {
    return [&shapes, measure](std::size_t begin, std::size_t end, std::string& out) {
      for (std::size_t t = begin; t < end; ++t) put(out, shapes[t].*measure);
    };
  };
  const std::vector<vtu::Array> arrays = {
      vtu::array<std::int64_t>(S::PointData, "Int64", "seed", 1, sites, sites,
                               [&](std::size_t begin, std::size_t end, std::string& out) {
                                 for (std::size_t c = begin; c < end; ++c)
                                   put(out, static_cast<std::int64_t>(mesh.cells[c].seed));
                               }),
      vtu::array<std::int32_t>(S::CellData, "Int32", "material", 1, tets, tets,
                               [&](std::size_t begin, std::size_t end, std::string& out) {
                                 for (std::size_t t = begin; t < end; ++t) put(out, dual.material[t]);
                               }),
      vtu::array<double>(S::CellData, "Float64", "min_dihedral", 1, tets, tets,
                         shape(&clipping::TetShape::min_dihedral)),
      vtu::array<double>(S::CellData, "Float64", "max_dihedral", 1, tets, tets,
                         shape(&clipping::TetShape::max_dihedral)),
      vtu::array<double>(S::CellData, "Float64", "radius_ratio", 1, tets, tets,
                         shape(&clipping::TetShape::radius_ratio)),
      vtu::array<double>(S::CellData, "Float64", "q4", 1, tets, tets, shape(&clipping::TetShape::q4)),
      vtu::array<double>(S::Points, "Float64", "Points", 3, 3 * sites, sites,
                         [&](std::size_t begin, std::size_t end, std::string& out) {
                           for (std::size_t c = begin; c < end; ++c) {
                             for (int k = 0; k < 3; ++k) put(out, mesh.cells[c].site[k]);
                           }
                         }),
      vtu::array<std::int64_t>(S::Cells, "Int64", "connectivity", 1, 4 * tets, tets,
                               [&](std::size_t begin, std::size_t end, std::string& out) {
                                 for (std::size_t t = begin; t < end; ++t) {
                                   for (std::uint32_t c : dual.tets[t]) put(out, static_cast<std::int64_t>(c));
                                 }
                               }),
      vtu::array<std::int64_t>(S::Cells, "Int64", "offsets", 1, tets, tets,
                               [](std::size_t begin, std::size_t end, std::string& out) {
                                 for (std::size_t t = begin; t < end; ++t)
                                   put(out, static_cast<std::int64_t>(4 * (t + 1)));
                               }),
      vtu::array<std::uint8_t>(S::Cells, "UInt8", "types", 1, tets, tets,
                               [](std::size_t begin, std::size_t end, std::string& out) {
                                 out.append(end - begin, static_cast<char>(kTetra));
                               }),
  };
  vtu::write_unstructured_grid(path, sites, tets, arrays);
}

}  // namespace vorocrust
