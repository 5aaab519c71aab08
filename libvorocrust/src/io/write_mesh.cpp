#include "vorocrust/write_mesh.hpp"

#include <cstring>
#include <iomanip>
#include <map>

#include "core/surface_measures.hpp"
#include "vorocrust/atomic_file.hpp"
#include "vorocrust/read_mesh.hpp"

namespace vorocrust {

namespace {

// Shortest text that reads back to the same double.
std::ostream& precise(std::ostream& out) { return out << std::setprecision(17); }

void write_off(const SurfaceMesh& mesh, std::ostream& out) {
  precise(out) << "OFF\n" << mesh.vertices.size() << ' ' << mesh.triangles.size() << " 0\n";
  for (const Point& p : mesh.vertices) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const Triangle& t : mesh.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

// Faces are written group by group; with region labels, one group per "BACK|FRONT" pair.
void write_obj(const SurfaceMesh& mesh, std::ostream& out) {
  precise(out) << "# written by libvorocrust\n";
  for (const Point& p : mesh.vertices) out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  const auto group_name = [&](std::size_t f) -> std::string {
    if (!mesh.has_regions()) return mesh.groups.empty() ? "mesh" : mesh.groups[mesh.face_group[f]].name;
    const RegionPair r = mesh.face_regions[f];
    const auto name = [&](std::int32_t i) { return i < 0 ? std::string("unknown") : mesh.region_names[i]; };
    return name(r.back) + "|" + name(r.front);
  };
  std::map<std::string, std::vector<std::size_t>> by_group;
  std::vector<std::string> order;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    auto [it, inserted] = by_group.try_emplace(group_name(f));
    if (inserted) order.push_back(it->first);
    it->second.push_back(f);
  }
  for (const std::string& name : order) {
    out << "g " << name << '\n';
    for (std::size_t f : by_group[name]) {
      const Triangle& t = mesh.triangles[f];
      out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    }
  }
}

void write_stl(const SurfaceMesh& mesh, std::ostream& out, bool ascii) {
  if (ascii) {
    precise(out) << "solid vorocrust\n";
    for (const Triangle& t : mesh.triangles) {
      const Point n = unit_normal(mesh.vertices, t);
      out << " facet normal " << n.x() << ' ' << n.y() << ' ' << n.z() << "\n  outer loop\n";
      for (Index v : t) out << "   vertex " << mesh.vertices[v].x() << ' ' << mesh.vertices[v].y() << ' ' << mesh.vertices[v].z() << '\n';
      out << "  endloop\n endfacet\n";
    }
    out << "endsolid vorocrust\n";
    return;
  }
  char header[80] = {};
  std::strncpy(header, "binary STL written by libvorocrust", sizeof header - 1);
  out.write(header, sizeof header);
  const std::uint32_t n = static_cast<std::uint32_t>(mesh.triangles.size());
  out.write(reinterpret_cast<const char*>(&n), 4);
  for (const Triangle& t : mesh.triangles) {
    float record[12];
    const Point normal = unit_normal(mesh.vertices, t);
    for (int i = 0; i < 3; ++i) record[i] = static_cast<float>(normal[i]);
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < 3; ++i) record[3 + 3 * c + i] = static_cast<float>(mesh.vertices[t[c]][i]);
    out.write(reinterpret_cast<const char*>(record), sizeof record);
    const std::uint16_t attribute = 0;
    out.write(reinterpret_cast<const char*>(&attribute), 2);
  }
}

void write_ply(const SurfaceMesh& mesh, std::ostream& out, bool ascii) {
  out << "ply\nformat " << (ascii ? "ascii" : "binary_little_endian") << " 1.0\ncomment written by libvorocrust\n";
  for (std::size_t r = 0; r < mesh.region_names.size(); ++r) {
    out << "comment vorocrust region " << r << ' ' << mesh.region_names[r] << '\n';
  }
  out << "element vertex " << mesh.vertices.size() << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "element face " << mesh.triangles.size() << "\nproperty list uchar int vertex_indices\n";
  if (mesh.has_regions()) out << "property int back_region\nproperty int front_region\n";
  out << "end_header\n";
  if (ascii) {
    precise(out);
    for (const Point& p : mesh.vertices) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
      const Triangle& t = mesh.triangles[f];
      out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2];
      if (mesh.has_regions()) out << ' ' << mesh.face_regions[f].back << ' ' << mesh.face_regions[f].front;
      out << '\n';
    }
    return;
  }
  for (const Point& p : mesh.vertices) out.write(reinterpret_cast<const char*>(p.data()), 3 * sizeof(double));
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const unsigned char three = 3;
    out.write(reinterpret_cast<const char*>(&three), 1);
    for (Index v : mesh.triangles[f]) {
      const std::int32_t i = static_cast<std::int32_t>(v);
      out.write(reinterpret_cast<const char*>(&i), 4);
    }
    if (mesh.has_regions()) {
      out.write(reinterpret_cast<const char*>(&mesh.face_regions[f].back), 4);
      out.write(reinterpret_cast<const char*>(&mesh.face_regions[f].front), 4);
    }
  }
}

}  // namespace

void write_mesh(const SurfaceMesh& mesh, const std::filesystem::path& path, const WriteOptions& options) {
  const MeshFormat format = format_from_extension(path);
  write_file_atomically(path, [&](std::ostream& out) {
    switch (format) {
      case MeshFormat::Off: write_off(mesh, out); break;
      case MeshFormat::Obj: write_obj(mesh, out); break;
      case MeshFormat::Stl: write_stl(mesh, out, options.ascii); break;
      case MeshFormat::Ply: write_ply(mesh, out, options.ascii); break;
    }
  });
}

}  // namespace vorocrust
