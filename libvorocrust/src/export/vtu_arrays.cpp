#include "export/vtu_arrays.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <ostream>

#include "vorocrust/atomic_file.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust::vtu {
namespace {

static_assert(std::endian::native == std::endian::little, "the files declare little-endian data");

constexpr std::size_t kBlock = 1 << 14;

const char* tag(Section s) {
  switch (s) {
    case Section::PointData: return "PointData";
    case Section::CellData: return "CellData";
    case Section::Points: return "Points";
    case Section::Cells: return "Cells";
  }
  return "";
}

}  // namespace

void write_unstructured_grid(const std::filesystem::path& path, std::size_t points, std::size_t cells,
                             const std::vector<Array>& arrays) {
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" +
      std::to_string(points) + "\" NumberOfCells=\"" + std::to_string(cells) + "\">\n";
  std::size_t offset = 0;
  const Array* open = nullptr;
  for (const Array& a : arrays) {
    if (open == nullptr || open->section != a.section) {
      if (open != nullptr) xml += std::string("</") + tag(open->section) + ">\n";
      xml += std::string("<") + tag(a.section) +
             (a.section == Section::CellData || a.section == Section::PointData
                  ? std::string(" Scalars=\"") + a.name + "\""
                  : std::string()) +
             ">\n";
      open = &a;
    }
    xml += std::string("<DataArray type=\"") + a.type + "\" Name=\"" + a.name + "\" NumberOfComponents=\"" +
           std::to_string(a.components) + "\" format=\"appended\" offset=\"" + std::to_string(offset) + "\"/>\n";
    offset += sizeof(std::uint64_t) + a.bytes();
  }
  if (open != nullptr) xml += std::string("</") + tag(open->section) + ">\n";
  xml += "</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_";
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
      if (written != header) {
        throw Error(Error::Kind::Internal,
                    path.filename().string() + ": array " + a.name + " came out of another size than declared");
      }
    }
    out << "\n</AppendedData>\n</VTKFile>\n";
  });
}

}  // namespace vorocrust::vtu
