#include "igaprep/mesh/write_surface.h"

#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <ostream>

#include <Eigen/Geometry>

#include "igaprep/core/atomic_file.h"
#include "igaprep/core/error.h"

namespace igaprep::mesh {

namespace {

std::string lower_extension(const std::string& path) {
  const auto slash = path.find_last_of("/\\");
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string e = path.substr(dot + 1);
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// Shortest decimal form that reads back to the same double (locale-free).
void put_double(std::ostream& out, double v) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  out.write(buf, res.ptr - buf);
}

void put_le32(std::ostream& out, uint32_t v) {
  const char b[4] = {static_cast<char>(v & 0xff), static_cast<char>((v >> 8) & 0xff),
                     static_cast<char>((v >> 16) & 0xff), static_cast<char>((v >> 24) & 0xff)};
  out.write(b, 4);
}

void put_float(std::ostream& out, double v) {
  const float f = static_cast<float>(v);
  uint32_t bits;
  std::memcpy(&bits, &f, 4);
  put_le32(out, bits);
}

void write_stl(std::ostream& out, const TriMesh& m) {
  char header[80] = {};
  std::strncpy(header, "igaprep binary STL", sizeof header - 1);
  out.write(header, 80);
  put_le32(out, static_cast<uint32_t>(m.F.rows()));
  for (int f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    Eigen::Vector3d n = (b - a).cross(c - a);
    const double len = n.norm();
    n = len > 0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::Zero();
    for (int d = 0; d < 3; ++d) put_float(out, n[d]);
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) put_float(out, m.V(m.F(f, k), d));
    out.write("\0\0", 2);  // attribute byte count
  }
}

void write_obj(std::ostream& out, const TriMesh& m) {
  out << "# igaprep surface: " << m.V.rows() << " vertices, " << m.F.rows() << " triangles\n";
  for (int i = 0; i < m.V.rows(); ++i) {
    out << "v";
    for (int d = 0; d < 3; ++d) {
      out << ' ';
      put_double(out, m.V(i, d));
    }
    out << '\n';
  }
  for (int f = 0; f < m.F.rows(); ++f)
    out << "f " << m.F(f, 0) + 1 << ' ' << m.F(f, 1) + 1 << ' ' << m.F(f, 2) + 1 << '\n';
}

void write_off(std::ostream& out, const TriMesh& m) {
  out << "OFF\n" << m.V.rows() << ' ' << m.F.rows() << " 0\n";
  for (int i = 0; i < m.V.rows(); ++i) {
    for (int d = 0; d < 3; ++d) {
      if (d) out << ' ';
      put_double(out, m.V(i, d));
    }
    out << '\n';
  }
  for (int f = 0; f < m.F.rows(); ++f) out << "3 " << m.F(f, 0) << ' ' << m.F(f, 1) << ' ' << m.F(f, 2) << '\n';
}

}  // namespace

void write_surface(const std::string& path, const TriMesh& mesh) {
  if (mesh.V.cols() != 3 || (mesh.F.size() > 0 && mesh.F.cols() != 3))
    throw bad_input(path + ": cannot write: the mesh is not a triangle mesh in 3D");
  if (mesh.F.size() > 0 && (mesh.F.minCoeff() < 0 || mesh.F.maxCoeff() >= mesh.V.rows()))
    throw bad_input(path + ": cannot write: a face refers to a vertex that does not exist");
  const std::string ext = lower_extension(path);
  if (ext == "stl")
    write_file_atomically(path, [&](std::ostream& out) { write_stl(out, mesh); }, true);
  else if (ext == "obj")
    write_file_atomically(path, [&](std::ostream& out) { write_obj(out, mesh); }, true);
  else if (ext == "off")
    write_file_atomically(path, [&](std::ostream& out) { write_off(out, mesh); }, true);
  else
    throw bad_input(path + ": cannot write surface: unknown extension '" + ext + "' (use .stl, .obj or .off)");
}

}  // namespace igaprep::mesh
