#pragma once
// Writing VTK XML data arrays and the file's frame (vtu_bezier.cpp,
// vtu_boundary.cpp).
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "number_text.h"

namespace igaprep::exporter::detail {

// One <DataArray>: ASCII inline, or an entry of the appended raw block.
// Binary arrays are remembered by address (no copy) and streamed by
// finish(); they must stay alive until then.
class ArrayWriter {
 public:
  ArrayWriter(std::ostream& out, bool binary) : out_(out), binary_(binary) {}

  template <class T>
  void array(const std::string& type, const std::string& name, int components, const std::vector<T>& v,
             const std::string& indent) {
    out_ << indent << "<DataArray type=\"" << type << "\" Name=\"" << name << "\"";
    if (components > 1) out_ << " NumberOfComponents=\"" << components << "\"";
    if (binary_) {
      const uint64_t bytes = v.size() * sizeof(T);
      out_ << " format=\"appended\" offset=\"" << offset_ << "\"/>\n";
      blocks_.push_back({reinterpret_cast<const char*>(v.data()), bytes});
      offset_ += sizeof(uint64_t) + bytes;
      return;
    }
    out_ << " format=\"ascii\">\n";
    for (size_t i = 0; i < v.size(); ++i) {
      if constexpr (std::is_floating_point_v<T>) out_ << detail::exact(v[i]);
      else out_ << static_cast<long long>(v[i]);
      out_ << ((i + 1) % static_cast<size_t>(components > 1 ? components : 8) == 0 ? "\n" : " ");
    }
    out_ << "\n" << indent << "</DataArray>\n";
  }

  void finish() {
    if (!binary_) return;
    out_ << " <AppendedData encoding=\"raw\">\n_";
    for (const auto& [data, bytes] : blocks_) {
      out_.write(reinterpret_cast<const char*>(&bytes), sizeof(uint64_t));
      if (bytes) out_.write(data, static_cast<std::streamsize>(bytes));
    }
    out_ << "\n </AppendedData>\n";
  }

 private:
  std::ostream& out_;
  bool binary_;
  uint64_t offset_ = 0;
  std::vector<std::pair<const char*, uint64_t>> blocks_;
};

inline bool little_endian() {
  const uint16_t x = 1;
  unsigned char c;
  std::memcpy(&c, &x, 1);
  return c == 1;
}

// The <VTKFile> header up to <Piece>, in this machine's byte order.
inline void vtu_header(std::ostream& out, std::size_t points, std::size_t cells) {
  out << "<?xml version=\"1.0\"?>\n";
  out << "<VTKFile type=\"UnstructuredGrid\" version=\"2.2\" byte_order=\""
      << (little_endian() ? "LittleEndian" : "BigEndian") << "\" header_type=\"UInt64\">\n";
  out << " <UnstructuredGrid>\n";
  out << "  <Piece NumberOfPoints=\"" << points << "\" NumberOfCells=\"" << cells << "\">\n";
}

// The end of the <CellData>, the piece's <Points> and <Cells>, then the
// file's end (the appended data of a binary writer).
inline void vtu_points_cells_and_end(std::ostream& out, ArrayWriter& w, const std::vector<double>& points,
                                     const std::vector<int64_t>& connectivity, const std::vector<int64_t>& offsets,
                                     const std::vector<uint8_t>& types) {
  out << "   </CellData>\n";
  out << "   <Points>\n";
  w.array("Float64", "Points", 3, points, "    ");
  out << "   </Points>\n";
  out << "   <Cells>\n";
  w.array("Int64", "connectivity", 1, connectivity, "    ");
  w.array("Int64", "offsets", 1, offsets, "    ");
  w.array("UInt8", "types", 1, types, "    ");
  out << "   </Cells>\n";
  out << "  </Piece>\n";
  out << " </UnstructuredGrid>\n";
  w.finish();
  out << "</VTKFile>\n";
}

}  // namespace igaprep::exporter::detail
