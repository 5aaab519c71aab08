// Internal: a VTK XML unstructured grid written as raw appended arrays, produced a block of
// items (cells or points) at a time, so that the file is never whole in memory.
//
// Contract of write_unstructured_grid(path, points, cells, arrays):
// - `arrays` come grouped by section in VTK's order (PointData, CellData, Points, Cells); each
//   declares its value type, name, components, value count and how many items it spans, and its
//   `produce(begin, end, out)` appends the raw little-endian values of items [begin, end).
// - Headers are UInt64 byte counts. The file is written atomically; Error(Output) when it
//   cannot be; Error(Internal) naming the array when one produces another size than it declared.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace vorocrust::vtu {

template <class T>
void put(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

enum class Section { PointData, CellData, Points, Cells };

struct Array {
  Section section;
  const char* type;  // VTK's: "Int32", "Float64", ...
  const char* name;
  int components;
  std::size_t count;  // values
  std::size_t value_bytes;
  std::size_t items;
  std::function<void(std::size_t begin, std::size_t end, std::string& out)> produce;
  std::size_t bytes() const { return count * value_bytes; }
};

template <class T>
Array array(Section section, const char* type, const char* name, int components, std::size_t count, std::size_t items,
            std::function<void(std::size_t, std::size_t, std::string&)> produce) {
  return {section, type, name, components, count, sizeof(T), items, std::move(produce)};
}

void write_unstructured_grid(const std::filesystem::path& path, std::size_t points, std::size_t cells,
                             const std::vector<Array>& arrays);

}  // namespace vorocrust::vtu
