#include "vorocrust/write_vtu.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "export/vtu_arrays.hpp"

namespace vorocrust {
namespace {

using vtu::put;

// A cell's faces, outward for it (as stored for their owner, reversed for their neighbour), and
// its points each once in the order the faces first visit them: the `faces` and `connectivity`
// of the file. `seen` marks points by the last cell that visited them.
class OutwardFaces {
 public:
  explicit OutwardFaces(const VoronoiMesh& mesh) : mesh_(mesh), seen_(mesh.points.size(), kUnseen) {}

  // face(n) before each face's n points, point(p) for each of them, first(p) for each point new
  // in the cell.
  template <class Face, class Vertex, class First>
  void walk(std::size_t c, Face&& face, Vertex&& point, First&& first) {
    for (const Index f : mesh_.cells[c].faces) {
      const std::vector<Index>& polygon = mesh_.faces[f].points;
      face(polygon.size());
      const bool owner = mesh_.faces[f].owner == static_cast<std::int32_t>(c);
      for (std::size_t k = 0; k < polygon.size(); ++k) {
        const Index p = owner ? polygon[k] : polygon[polygon.size() - 1 - k];
        point(p);
        if (seen_[p] != c) seen_[p] = c, first(p);
      }
    }
  }
  // Forgets the cells walked, for a walk over them again.
  void restart() { std::fill(seen_.begin(), seen_.end(), kUnseen); }

 private:
  static constexpr std::size_t kUnseen = SIZE_MAX;
  const VoronoiMesh& mesh_;
  std::vector<std::size_t> seen_;
};

}  // namespace

void write_vtu(const VoronoiMesh& mesh, const std::filesystem::path& path, const CellQuality* quality) {
  std::optional<CellQuality> measured;
  if (quality == nullptr || quality->cells.size() != mesh.cells.size()) {
    // A mesh without cells has no quality to measure (measure_cell_quality refuses it).
    measured = mesh.cells.empty() ? CellQuality{} : measure_cell_quality(mesh);
    quality = &*measured;
  }
  constexpr std::uint8_t kPolyhedron = 42;
  const std::size_t cells = mesh.cells.size();
  OutwardFaces outward(mesh);
  // Each cell's count of distinct points and the lengths of `connectivity` and `faces`, from a
  // walk that writes nothing.
  std::vector<std::uint32_t> distinct(cells, 0);
  std::size_t connectivity = 0, faces = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    faces += 1;
    outward.walk(c, [&](std::size_t) { ++faces; }, [&](Index) { ++faces; }, [&](Index) { ++distinct[c]; });
    connectivity += distinct[c];
  }
  outward.restart();
  std::int64_t connectivity_end = 0, faces_end = 0;
  const auto per_cell = [&](auto value) {
    return [&mesh, &quality, value](std::size_t begin, std::size_t end, std::string& out) {
      for (std::size_t c = begin; c < end; ++c) put(out, value(mesh.cells[c], quality->cells[c]));
    };
  };
  using Cell = const VoronoiCell&;
  using Shape = const CellShape&;
  using S = vtu::Section;
  const std::vector<vtu::Array> arrays = {
      vtu::array<std::int32_t>(S::CellData, "Int32", "material", 1, cells, cells, per_cell([](Cell c, Shape) { return c.region; })),
      vtu::array<std::int64_t>(S::CellData, "Int64", "seed", 1, cells, cells,
                          per_cell([](Cell c, Shape) { return static_cast<std::int64_t>(c.seed); })),
      vtu::array<double>(S::CellData, "Float64", "volume", 1, cells, cells, per_cell([](Cell c, Shape) { return c.volume; })),
      vtu::array<double>(S::CellData, "Float64", "aspect_ratio", 1, cells, cells, per_cell([](Cell, Shape s) { return s.aspect_ratio; })),
      vtu::array<double>(S::Points, "Float64", "Points", 3, 3 * mesh.points.size(), mesh.points.size(),
                    [&](std::size_t begin, std::size_t end, std::string& out) {
                      for (std::size_t p = begin; p < end; ++p) {
                        for (int k = 0; k < 3; ++k) put(out, mesh.points[p][k]);
                      }
                    }),
      vtu::array<std::int64_t>(S::Cells, "Int64", "connectivity", 1, connectivity, cells,
                          [&](std::size_t begin, std::size_t end, std::string& out) {
                            for (std::size_t c = begin; c < end; ++c) {
                              outward.walk(c, [](std::size_t) {}, [](Index) {},
                                           [&](Index p) { put(out, static_cast<std::int64_t>(p)); });
                            }
                          }),
      vtu::array<std::int64_t>(S::Cells, "Int64", "offsets", 1, cells, cells, [&](std::size_t begin, std::size_t end, std::string& out) {
        for (std::size_t c = begin; c < end; ++c) put(out, connectivity_end += distinct[c]);
      }),
      vtu::array<std::uint8_t>(S::Cells, "UInt8", "types", 1, cells, cells,
                          [](std::size_t begin, std::size_t end, std::string& out) { out.append(end - begin, static_cast<char>(kPolyhedron)); }),
      vtu::array<std::int64_t>(S::Cells, "Int64", "faces", 1, faces, cells, [&](std::size_t begin, std::size_t end, std::string& out) {
        for (std::size_t c = begin; c < end; ++c) {
          put(out, static_cast<std::int64_t>(mesh.cells[c].faces.size()));
          outward.walk(c, [&](std::size_t n) { put(out, static_cast<std::int64_t>(n)); },
                       [&](Index p) { put(out, static_cast<std::int64_t>(p)); }, [](Index) {});
        }
      }),
      vtu::array<std::int64_t>(S::Cells, "Int64", "faceoffsets", 1, cells, cells, [&](std::size_t begin, std::size_t end, std::string& out) {
        for (std::size_t c = begin; c < end; ++c) {
          faces_end += 1;
          for (const Index f : mesh.cells[c].faces) faces_end += 1 + static_cast<std::int64_t>(mesh.faces[f].points.size());
          put(out, faces_end);
        }
      }),
  };
  vtu::write_unstructured_grid(path, mesh.points.size(), cells, arrays);
}

}  // namespace vorocrust
