#include "vorocrust/write_vtu.hpp"

#include <bit>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "vorocrust/atomic_file.hpp"

namespace vorocrust {
namespace {

static_assert(std::endian::native == std::endian::little, "mesh.vtu declares little-endian data");

// The arrays of the file, in the order they are declared and appended.
struct Arrays {
  std::vector<std::int32_t> material;
  std::vector<std::int64_t> seed;
  std::vector<double> volume, aspect_ratio;
  std::vector<double> points;
  std::vector<std::int64_t> connectivity, offsets, faces, face_offsets;
  std::vector<std::uint8_t> types;
};

Arrays make_arrays(const VoronoiMesh& mesh, const CellQuality& quality) {
  constexpr std::uint8_t kPolyhedron = 42;
  Arrays a;
  for (const CellShape& shape : quality.cells) a.aspect_ratio.push_back(shape.aspect_ratio);
  for (const Point& p : mesh.points) a.points.insert(a.points.end(), {p.x(), p.y(), p.z()});
  std::vector<std::size_t> seen(mesh.points.size(), SIZE_MAX);
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    const VoronoiCell& cell = mesh.cells[c];
    a.material.push_back(cell.region);
    a.seed.push_back(cell.seed);
    a.volume.push_back(cell.volume);
    a.types.push_back(kPolyhedron);
    a.faces.push_back(static_cast<std::int64_t>(cell.faces.size()));
    for (Index f : cell.faces) {
      const std::vector<Index>& polygon = mesh.faces[f].points;
      a.faces.push_back(static_cast<std::int64_t>(polygon.size()));
      // Outward for this cell: as stored for its owner, reversed for its neighbour.
      const bool owner = mesh.faces[f].owner == static_cast<std::int32_t>(c);
      for (std::size_t k = 0; k < polygon.size(); ++k) {
        const Index p = owner ? polygon[k] : polygon[polygon.size() - 1 - k];
        a.faces.push_back(p);
        if (seen[p] != c) seen[p] = c, a.connectivity.push_back(p);
      }
    }
    a.offsets.push_back(static_cast<std::int64_t>(a.connectivity.size()));
    a.face_offsets.push_back(static_cast<std::int64_t>(a.faces.size()));
  }
  return a;
}

class Appended {
 public:
  // The DataArray element for `data`, noting it for the appended section.
  template <class T>
  std::string declare(const std::vector<T>& data, const char* type, const char* name, int components = 1) {
    std::string xml = std::string("<DataArray type=\"") + type + "\" Name=\"" + name + "\" NumberOfComponents=\"" +
                      std::to_string(components) + "\" format=\"appended\" offset=\"" + std::to_string(offset_) + "\"/>\n";
    blocks_.push_back({reinterpret_cast<const char*>(data.data()), data.size() * sizeof(T)});
    offset_ += sizeof(std::uint64_t) + data.size() * sizeof(T);
    return xml;
  }

  void write(std::ostream& out) const {
    for (const auto& [bytes, size] : blocks_) {
      const std::uint64_t header = size;
      out.write(reinterpret_cast<const char*>(&header), sizeof header);
      out.write(bytes, static_cast<std::streamsize>(size));
    }
  }

 private:
  std::vector<std::pair<const char*, std::size_t>> blocks_;
  std::size_t offset_ = 0;
};

}  // namespace

void write_vtu(const VoronoiMesh& mesh, const std::filesystem::path& path, const CellQuality* quality) {
  std::optional<CellQuality> measured;
  if (quality == nullptr || quality->cells.size() != mesh.cells.size()) {
    // A mesh without cells has no quality to measure (measure_cell_quality refuses it).
    measured = mesh.cells.empty() ? CellQuality{} : measure_cell_quality(mesh);
    quality = &*measured;
  }
  const Arrays a = make_arrays(mesh, *quality);
  Appended data;
  std::string xml = "<?xml version=\"1.0\"?>\n"
                    "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
                    "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" + std::to_string(mesh.points.size()) +
                    "\" NumberOfCells=\"" + std::to_string(mesh.cells.size()) + "\">\n";
  xml += "<CellData Scalars=\"material\">\n";
  xml += data.declare(a.material, "Int32", "material");
  xml += data.declare(a.seed, "Int64", "seed");
  xml += data.declare(a.volume, "Float64", "volume");
  xml += data.declare(a.aspect_ratio, "Float64", "aspect_ratio");
  xml += "</CellData>\n<Points>\n";
  xml += data.declare(a.points, "Float64", "Points", 3);
  xml += "</Points>\n<Cells>\n";
  xml += data.declare(a.connectivity, "Int64", "connectivity");
  xml += data.declare(a.offsets, "Int64", "offsets");
  xml += data.declare(a.types, "UInt8", "types");
  xml += data.declare(a.faces, "Int64", "faces");
  xml += data.declare(a.face_offsets, "Int64", "faceoffsets");
  xml += "</Cells>\n</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_";
  write_file_atomically(path, [&](std::ostream& out) {
    out << xml;
    data.write(out);
    out << "\n</AppendedData>\n</VTKFile>\n";
  });
}

}  // namespace vorocrust
