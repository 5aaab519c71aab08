#include "vorocrust/write_vtu.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "vorocrust/atomic_file.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust {
namespace {

static_assert(std::endian::native == std::endian::little, "mesh.vtu declares little-endian data");

// Values go to the file a block of this many cells (or points) at a time: the file is never
// whole in memory, only the mesh it is written from.
constexpr std::size_t kBlock = 1 << 14;

template <class T>
void put(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

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

// One array of the appended section: declared with its size in bytes, then produced a block of
// its items (cells or points) at a time, in order.
struct Array {
  const char* type;
  const char* name;
  int components;
  std::size_t count;  // values
  std::size_t value_bytes;
  std::size_t items;
  std::function<void(std::size_t begin, std::size_t end, std::string& out)> produce;
  std::size_t bytes() const { return count * value_bytes; }
};

template <class T>
Array array(const char* type, const char* name, int components, std::size_t count, std::size_t items,
            std::function<void(std::size_t, std::size_t, std::string&)> produce) {
  return {type, name, components, count, sizeof(T), items, std::move(produce)};
}

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
  const std::vector<Array> arrays = {
      array<std::int32_t>("Int32", "material", 1, cells, cells, per_cell([](Cell c, Shape) { return c.region; })),
      array<std::int64_t>("Int64", "seed", 1, cells, cells,
                          per_cell([](Cell c, Shape) { return static_cast<std::int64_t>(c.seed); })),
      array<double>("Float64", "volume", 1, cells, cells, per_cell([](Cell c, Shape) { return c.volume; })),
      array<double>("Float64", "aspect_ratio", 1, cells, cells, per_cell([](Cell, Shape s) { return s.aspect_ratio; })),
      array<double>("Float64", "Points", 3, 3 * mesh.points.size(), mesh.points.size(),
                    [&](std::size_t begin, std::size_t end, std::string& out) {
                      for (std::size_t p = begin; p < end; ++p) {
                        for (int k = 0; k < 3; ++k) put(out, mesh.points[p][k]);
                      }
                    }),
      array<std::int64_t>("Int64", "connectivity", 1, connectivity, cells,
                          [&](std::size_t begin, std::size_t end, std::string& out) {
                            for (std::size_t c = begin; c < end; ++c) {
                              outward.walk(c, [](std::size_t) {}, [](Index) {},
                                           [&](Index p) { put(out, static_cast<std::int64_t>(p)); });
                            }
                          }),
      array<std::int64_t>("Int64", "offsets", 1, cells, cells, [&](std::size_t begin, std::size_t end, std::string& out) {
        for (std::size_t c = begin; c < end; ++c) put(out, connectivity_end += distinct[c]);
      }),
      array<std::uint8_t>("UInt8", "types", 1, cells, cells,
                          [](std::size_t begin, std::size_t end, std::string& out) { out.append(end - begin, static_cast<char>(kPolyhedron)); }),
      array<std::int64_t>("Int64", "faces", 1, faces, cells, [&](std::size_t begin, std::size_t end, std::string& out) {
        for (std::size_t c = begin; c < end; ++c) {
          put(out, static_cast<std::int64_t>(mesh.cells[c].faces.size()));
          outward.walk(c, [&](std::size_t n) { put(out, static_cast<std::int64_t>(n)); },
                       [&](Index p) { put(out, static_cast<std::int64_t>(p)); }, [](Index) {});
        }
      }),
      array<std::int64_t>("Int64", "faceoffsets", 1, cells, cells, [&](std::size_t begin, std::size_t end, std::string& out) {
        for (std::size_t c = begin; c < end; ++c) {
          faces_end += 1;
          for (const Index f : mesh.cells[c].faces) faces_end += 1 + static_cast<std::int64_t>(mesh.faces[f].points.size());
          put(out, faces_end);
        }
      }),
  };
  std::string xml = "<?xml version=\"1.0\"?>\n"
                    "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
                    "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" + std::to_string(mesh.points.size()) +
                    "\" NumberOfCells=\"" + std::to_string(cells) + "\">\n";
  std::size_t offset = 0;
  for (const Array& a : arrays) {
    const std::string name = a.name;
    if (name == "material") xml += "<CellData Scalars=\"material\">\n";
    if (name == "Points") xml += "</CellData>\n<Points>\n";
    if (name == "connectivity") xml += "</Points>\n<Cells>\n";
    xml += std::string("<DataArray type=\"") + a.type + "\" Name=\"" + a.name + "\" NumberOfComponents=\"" +
           std::to_string(a.components) + "\" format=\"appended\" offset=\"" + std::to_string(offset) + "\"/>\n";
    offset += sizeof(std::uint64_t) + a.bytes();
  }
  xml += "</Cells>\n</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_";
  write_file_atomically(path, [&](std::ostream& out) {
    out << xml;
    std::string block;
    for (const Array& a : arrays) {
      const std::uint64_t header = a.bytes();
      out.write(reinterpret_cast<const char*>(&header), sizeof header);
      std::size_t written = 0;
      for (std::size_t begin = 0; begin < a.items; begin += kBlock) {
        block.clear();
        a.produce(begin, std::min(a.items, begin + kBlock), block);
        out.write(block.data(), static_cast<std::streamsize>(block.size()));
        written += block.size();
      }
      if (written != header) throw Error(Error::Kind::Internal, std::string("mesh.vtu: array ") + a.name + " came out of another size than declared");
    }
    out << "\n</AppendedData>\n</VTKFile>\n";
  });
}

}  // namespace vorocrust
