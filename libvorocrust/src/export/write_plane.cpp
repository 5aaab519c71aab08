// A 2D mesh as files: VTK polygons, an SVG picture, and the slab one cell thick that the 3D
// writers (OpenFOAM, TOUGH, PFLOTRAN, Exodus) take.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

#include "io/text_numbers.hpp"
#include "vorocrust/atomic_file.hpp"
#include "vorocrust/plane.hpp"

namespace vorocrust {

VoronoiMesh extrude_plane_mesh(const PlaneMesh& mesh, double thickness) {
  if (!(thickness > 0) || !std::isfinite(thickness)) {
    throw Error(Error::Kind::Usage, "thickness must be positive", {.option = "thickness"});
  }
  VoronoiMesh out;
  const auto n = static_cast<Index>(mesh.points.size());
  for (const Point2& p : mesh.points) out.points.emplace_back(p.x(), p.y(), 0);
  for (const Point2& p : mesh.points) out.points.emplace_back(p.x(), p.y(), thickness);
  out.region_names = mesh.region_names;
  out.empty_region = static_cast<std::int32_t>(out.region_names.size());
  out.region_names.push_back("frontAndBack");
  out.cells.resize(mesh.cells.size());
  for (std::size_t i = 0; i < mesh.cells.size(); ++i) {
    const PlaneCell& c = mesh.cells[i];
    VoronoiCell& cell = out.cells[i];
    const Point& seed = mesh.seeds[c.seed].position;
    cell.seed = c.seed;
    cell.site = Point(seed.x(), seed.y(), thickness / 2);
    cell.region = c.region;
    cell.seed_kind = mesh.seeds[c.seed].kind;
    cell.volume = c.area * thickness;
    cell.centroid = Point(c.centroid.x(), c.centroid.y(), thickness / 2);
    const auto add = [&](VoronoiFace face) {
      cell.faces.push_back(static_cast<Index>(out.faces.size()));
      if (face.neighbour != kNoCell) out.cells[static_cast<std::size_t>(face.neighbour)].faces.push_back(static_cast<Index>(out.faces.size()));
      out.faces.push_back(std::move(face));
    };
    const auto self = static_cast<std::int32_t>(i);
    const std::size_t m = c.points.size();
    for (std::size_t k = 0; k < m; ++k) {
      const std::int32_t j = c.across[k];
      if (j != kNoCell && j < self) continue;  // listed by the lower cell
      const Index a = c.points[k], b = c.points[(k + 1) % m];
      VoronoiFace face;
      face.points = {a, b, b + n, a + n};  // its normal points out of the cell, right of a -> b
      face.owner = self;
      face.neighbour = j;
      face.owner_seed = c.seed;
      face.neighbour_seed = c.seeds_across[k] < 0 ? c.seed : static_cast<Index>(c.seeds_across[k]);
      face.regions = {c.region, c.regions_across[k]};
      add(std::move(face));
    }
    VoronoiFace front, back;
    for (std::size_t k = m; k-- > 0;) front.points.push_back(c.points[k]);
    for (Index v : c.points) back.points.push_back(v + n);
    for (VoronoiFace* face : {&front, &back}) {
      face->owner = self;
      face->owner_seed = face->neighbour_seed = c.seed;
      face->regions = {c.region, out.empty_region};
      add(std::move(*face));
    }
  }
  return out;
}

void write_plane_vtu(const PlaneMesh& mesh, const std::filesystem::path& path, const PlaneQuality* given) {
  const PlaneQuality quality = given ? PlaneQuality{} : measure_plane_quality(mesh);
  const PlaneQuality& q = given ? *given : quality;
  std::string t;
  t += "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n";
  t += "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" + std::to_string(mesh.points.size()) + "\" NumberOfCells=\"" +
       std::to_string(mesh.cells.size()) + "\">\n";
  t += "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const Point2& p : mesh.points) {
    io::append_number(t, p.x());
    t += ' ';
    io::append_number(t, p.y());
    t += " 0\n";
  }
  t += "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const PlaneCell& c : mesh.cells) {
    for (Index v : c.points) {
      io::append_number(t, static_cast<long long>(v));
      t += ' ';
    }
    t += '\n';
  }
  t += "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  long long offset = 0;
  for (const PlaneCell& c : mesh.cells) {
    offset += static_cast<long long>(c.points.size());
    io::append_number(t, offset);
    t += '\n';
  }
  t += "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < mesh.cells.size(); ++i) t += "7\n";  // VTK_POLYGON
  t += "</DataArray>\n</Cells>\n<CellData Scalars=\"material\">\n";
  const auto array = [&](const char* type, const char* name, auto value) {
    t += std::string("<DataArray type=\"") + type + "\" Name=\"" + name + "\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < mesh.cells.size(); ++i) {
      io::append_number(t, value(i));
      t += '\n';
    }
    t += "</DataArray>\n";
  };
  array("Int32", "material", [&](std::size_t i) { return static_cast<long long>(mesh.cells[i].region); });
  array("Int64", "seed", [&](std::size_t i) { return static_cast<long long>(mesh.cells[i].seed); });
  array("Float64", "area", [&](std::size_t i) { return mesh.cells[i].area; });
  array("Float64", "aspect_ratio", [&](std::size_t i) { return q.aspect_ratio[i]; });
  t += "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  write_file_atomically(path, t);
}

void write_plane_svg(const PlaneMesh& mesh, const std::filesystem::path& path) {
  const PlanarDomain& domain = mesh.domain;
  Eigen::AlignedBox2d box;
  for (const auto& s : domain.segments) {
    box.extend(domain.points[s[0]]);
    box.extend(domain.points[s[1]]);
  }
  for (const Point2& p : mesh.points) box.extend(p);
  const double size = std::max(box.sizes().x(), box.sizes().y());
  const double pad = 0.03 * size;
  box = Eigen::AlignedBox2d(box.min() - Point2::Constant(pad), box.max() + Point2::Constant(pad));
  // 1000 pixels across the longer side; y up, as the domain's coordinates are.
  const double scale = 1000 / std::max(box.sizes().x(), box.sizes().y());
  const auto X = [&](double x) { return (x - box.min().x()) * scale; };
  const auto Y = [&](double y) { return (box.max().y() - y) * scale; };
  const auto num = [](std::string& out, double x) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, x, std::chars_format::fixed, 2).ptr;
    out.append(text, end);
  };
  static constexpr const char* kColours[] = {"#8dd3c7", "#ffffb3", "#bebada", "#fb8072", "#80b1d3", "#fdb462",
                                             "#b3de69", "#fccde5", "#d9d9d9", "#bc80bd", "#ccebc5", "#ffed6f"};
  std::string t = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"";
  num(t, box.sizes().x() * scale);
  t += "\" height=\"";
  num(t, box.sizes().y() * scale);
  t += "\">\n<title>Conforming Voronoi mesh: " + std::to_string(mesh.cells.size()) + " cells</title>\n";
  t += "<g stroke=\"#333\" stroke-width=\"0.4\" stroke-linejoin=\"round\">\n";
  for (const PlaneCell& c : mesh.cells) {
    t += "<polygon fill=\"";
    t += kColours[static_cast<std::size_t>(std::max(c.region - 1, 0)) % std::size(kColours)];
    t += "\" points=\"";
    for (Index v : c.points) {
      num(t, X(mesh.points[v].x()));
      t += ',';
      num(t, Y(mesh.points[v].y()));
      t += ' ';
    }
    t += "\"/>\n";
  }
  t += "</g>\n<g fill=\"#222\">\n";
  for (const PlaneCell& c : mesh.cells) {
    const Point& s = mesh.seeds[c.seed].position;
    t += "<circle cx=\"";
    num(t, X(s.x()));
    t += "\" cy=\"";
    num(t, Y(s.y()));
    t += "\" r=\"";
    num(t, std::clamp(0.08 * std::sqrt(std::abs(c.area)) * scale, 0.3, 2.0));
    t += "\"/>\n";
  }
  t += "</g>\n<g stroke=\"#c00\" stroke-width=\"1.2\" stroke-linecap=\"round\">\n";
  for (const auto& s : domain.segments) {
    const Point2 &a = domain.points[s[0]], &b = domain.points[s[1]];
    t += "<line x1=\"";
    num(t, X(a.x()));
    t += "\" y1=\"";
    num(t, Y(a.y()));
    t += "\" x2=\"";
    num(t, X(b.x()));
    t += "\" y2=\"";
    num(t, Y(b.y()));
    t += "\"/>\n";
  }
  t += "</g>\n</svg>\n";
  write_file_atomically(path, t);
}

}  // namespace vorocrust
