#include "igaprep/mesh/read_surface.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "igaprep/core/error.h"
#include "igaprep/core/input_files.h"

namespace igaprep::mesh {

namespace {

// Everything a reader collects before it becomes a TriMesh.
struct Soup {
  std::vector<double> xyz;  // 3 per vertex
  std::vector<int> tri;     // 3 per triangle
  int num_vertices() const { return static_cast<int>(xyz.size() / 3); }
};

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string extension(const std::string& path) {
  const auto slash = path.find_last_of("/\\");
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  return lower(path.substr(dot + 1));
}

bool parse_double(std::string_view tok, double& out) {
  if (!tok.empty() && tok.front() == '+') tok.remove_prefix(1);
  if (tok.empty()) return false;
  const auto res = std::from_chars(tok.data(), tok.data() + tok.size(), out);
  return res.ec == std::errc() && res.ptr == tok.data() + tok.size();
}

bool parse_long(std::string_view tok, long& out) {
  if (!tok.empty() && tok.front() == '+') tok.remove_prefix(1);
  if (tok.empty()) return false;
  const auto res = std::from_chars(tok.data(), tok.data() + tok.size(), out);
  return res.ec == std::errc() && res.ptr == tok.data() + tok.size();
}

// Splits text into lines and whitespace-separated tokens, knowing line numbers
// (1-based) for the messages.
class Lexer {
 public:
  explicit Lexer(std::string_view text, size_t start = 0, char comment = '\0')
      : text_(text), pos_(start), comment_(comment) {
    for (size_t i = 0; i < start && i < text.size(); ++i)
      if (text[i] == '\n') ++line_;
  }
  // Next token, or empty at the end of the text.
  std::string_view next() {
    skip_space();
    const size_t begin = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
    return text_.substr(begin, pos_ - begin);
  }
  // Tokens of the next line that has any (comments removed); false at the end.
  bool next_line(std::vector<std::string_view>& tokens) {
    tokens.clear();
    while (pos_ < text_.size()) {
      size_t end = text_.find('\n', pos_);
      if (end == std::string_view::npos) end = text_.size();
      std::string_view line = text_.substr(pos_, end - pos_);
      current_line_ = line_;
      pos_ = end + 1;
      ++line_;
      if (comment_) {
        const size_t c = line.find(comment_);
        if (c != std::string_view::npos) line = line.substr(0, c);
      }
      size_t i = 0;
      while (i < line.size()) {
        while (i < line.size() && is_space(line[i])) ++i;
        const size_t b = i;
        while (i < line.size() && !is_space(line[i])) ++i;
        if (i > b) tokens.push_back(line.substr(b, i - b));
      }
      if (!tokens.empty()) return true;
    }
    return false;
  }
  void skip_line() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
  }
  int line() const { return line_; }                  // line of the last token from next()
  int current_line() const { return current_line_; }  // line returned by next_line()

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }
  void skip_space() {
    for (;;) {
      while (pos_ < text_.size() && is_space(text_[pos_])) {
        if (text_[pos_] == '\n') ++line_;
        ++pos_;
      }
      if (comment_ && pos_ < text_.size() && text_[pos_] == comment_) {
        skip_line();
        continue;
      }
      return;
    }
  }
  std::string_view text_;
  size_t pos_ = 0;
  char comment_;
  int line_ = 1;
  int current_line_ = 1;
};

class Reader {
 public:
  Reader(std::string path, std::string data) : path_(std::move(path)), data_(std::move(data)) {}

  [[noreturn]] void fail(const std::string& what) const { throw bad_input(path_ + ": " + what); }

  void add_vertex(Soup& s, double x, double y, double z, const std::string& where) const {
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
      fail("NaN or infinite coordinate at vertex " + std::to_string(s.num_vertices()) + " (" + where + ")");
    s.xyz.insert(s.xyz.end(), {x, y, z});
  }

  double number(std::string_view tok, int line, const char* what) const {
    double v;
    if (tok.empty()) fail("truncated: file ends where " + std::string(what) + " was expected (line " +
                          std::to_string(line) + ")");
    if (!parse_double(tok, v))
      fail("line " + std::to_string(line) + ": expected " + what + ", found '" + std::string(tok) + "'");
    return v;
  }

  // Fan-triangulates polygon `poly` (0-based indices) into s.tri.
  void add_polygon(Soup& s, const std::vector<long>& poly, const std::string& where) const {
    if (poly.size() < 3)
      fail("face with " + std::to_string(poly.size()) + " vertices (at least 3 needed) at " + where);
    for (size_t k = 1; k + 1 < poly.size(); ++k)
      s.tri.insert(s.tri.end(), {static_cast<int>(poly[0]), static_cast<int>(poly[k]), static_cast<int>(poly[k + 1])});
  }

  void check_indices(const Soup& s) const {
    const long n = s.num_vertices();
    for (size_t i = 0; i < s.tri.size(); ++i)
      if (s.tri[i] < 0 || s.tri[i] >= n)
        fail("face " + std::to_string(i / 3) + " refers to vertex " + std::to_string(s.tri[i]) +
             " (0-based), but the file has only " + std::to_string(n) + " vertices");
  }

  TriMesh read() {
    if (data_.find_first_not_of(" \t\r\n\v\f") == std::string::npos) fail("empty file");
    Soup s;
    switch (detect()) {
      case Format::StlAscii: s = read_stl_ascii(); break;
      case Format::StlBinary: s = read_stl_binary(); break;
      case Format::Obj: s = read_obj(); break;
      case Format::Off: s = read_off(); break;
      case Format::Ply: s = read_ply(); break;
      case Format::Unknown:
        fail("unknown format: the content is not STL (ASCII or binary), OBJ, OFF or PLY");
    }
    if (s.tri.empty()) fail("no faces (empty surface)");
    check_indices(s);
    TriMesh m;
    m.V.resize(s.num_vertices(), 3);
    for (int i = 0; i < s.num_vertices(); ++i)
      for (int d = 0; d < 3; ++d) m.V(i, d) = s.xyz[3 * i + d];
    const int nf = static_cast<int>(s.tri.size() / 3);
    m.F.resize(nf, 3);
    for (int f = 0; f < nf; ++f)
      for (int k = 0; k < 3; ++k) m.F(f, k) = s.tri[3 * f + k];
    return m;
  }

 private:
  enum class Format { StlAscii, StlBinary, Obj, Off, Ply, Unknown };

  // First token of the text, skipping blank lines and '#' comment lines.
  std::string first_token() const {
    Lexer lex(data_, 0, '#');
    return std::string(lex.next());
  }

  bool binary_stl_size_matches() const {
    if (data_.size() < 84) return false;
    uint32_t n;
    std::memcpy(&n, data_.data() + 80, 4);
    n = le32(n);
    return data_.size() == 84 + 50 * static_cast<uint64_t>(n);
  }

  bool looks_like_text(size_t upto) const {
    const size_t n = std::min(upto, data_.size());
    for (size_t i = 0; i < n; ++i) {
      const unsigned char c = static_cast<unsigned char>(data_[i]);
      if (c < 9 || (c > 13 && c < 32) || c == 127) return false;
    }
    return true;
  }

  Format detect() const {
    if (data_.compare(0, 3, "ply") == 0 && data_.size() > 3 && (data_[3] == '\n' || data_[3] == '\r')) return Format::Ply;
    const bool starts_solid = data_.compare(0, 5, "solid") == 0;
    if (binary_stl_size_matches()) {
      // Some binary STL headers start with "solid" too; ASCII STL is all text.
      if (!(starts_solid && looks_like_text(std::min<size_t>(data_.size(), 1000)) &&
            data_.find("facet", 0) != std::string::npos))
        return Format::StlBinary;
    }
    const std::string tok = first_token();
    if (tok == "solid" && looks_like_text(std::min<size_t>(data_.size(), 1000))) return Format::StlAscii;
    if (tok.size() >= 3 && tok.size() <= 7 && tok.compare(tok.size() - 3, 3, "OFF") == 0 &&
        tok.find_first_not_of("STCNOFF") == std::string::npos)
      return Format::Off;
    static const char* obj_keywords[] = {"v", "vt", "vn", "vp", "f", "o", "g", "s", "l", "p", "mtllib", "usemtl"};
    for (const char* k : obj_keywords)
      if (tok == k) return Format::Obj;
    // A binary STL whose size disagrees with its triangle count is truncated.
    if (extension(path_) == "stl" && (!starts_solid || !looks_like_text(std::min<size_t>(data_.size(), 1000))))
      return Format::StlBinary;
    return Format::Unknown;
  }

  static uint32_t le32(uint32_t v) {
    const uint16_t probe = 1;
    unsigned char b;
    std::memcpy(&b, &probe, 1);
    if (b == 1) return v;
    return ((v & 0xffu) << 24) | ((v & 0xff00u) << 8) | ((v >> 8) & 0xff00u) | (v >> 24);
  }

  // STL stores every corner separately: merge corners with identical coordinates.
  struct KeyHash {
    size_t operator()(const std::array<double, 3>& k) const {
      size_t h = 1469598103934665603ull;
      for (double d : k) {
        uint64_t bits;
        std::memcpy(&bits, &d, 8);
        h = (h ^ bits) * 1099511628211ull;
        h ^= h >> 29;
      }
      return h;
    }
  };
  class Merger {
   public:
    int index(Soup& s, const Reader& r, double x, double y, double z, const std::string& where) {
      std::array<double, 3> k{x + 0.0, y + 0.0, z + 0.0};  // + 0.0 turns -0 into +0
      auto it = map_.find(k);
      if (it != map_.end()) return it->second;
      const int id = s.num_vertices();
      r.add_vertex(s, k[0], k[1], k[2], where);
      map_.emplace(k, id);
      return id;
    }

   private:
    std::unordered_map<std::array<double, 3>, int, KeyHash> map_;
  };

  Soup read_stl_binary() const {
    if (data_.size() < 84)
      fail("truncated binary STL: " + std::to_string(data_.size()) + " bytes, shorter than the 84-byte header");
    uint32_t n;
    std::memcpy(&n, data_.data() + 80, 4);
    n = le32(n);
    const uint64_t need = 84 + 50 * static_cast<uint64_t>(n);
    if (data_.size() < need)
      fail("truncated binary STL: header declares " + std::to_string(n) + " triangles (" + std::to_string(need) +
           " bytes) but the file has " + std::to_string(data_.size()) + " bytes");
    if (data_.size() > need)
      fail("corrupt binary STL: header declares " + std::to_string(n) + " triangles (" + std::to_string(need) +
           " bytes) but the file has " + std::to_string(data_.size()) + " bytes");
    Soup s;
    Merger merge;
    s.tri.reserve(3 * n);
    for (uint32_t t = 0; t < n; ++t) {
      const char* p = data_.data() + 84 + 50 * static_cast<size_t>(t) + 12;
      for (int c = 0; c < 3; ++c) {
        float f[3];
        for (int d = 0; d < 3; ++d) {
          uint32_t bits;
          std::memcpy(&bits, p + 12 * c + 4 * d, 4);
          bits = le32(bits);
          std::memcpy(&f[d], &bits, 4);
        }
        s.tri.push_back(merge.index(s, *this, f[0], f[1], f[2], "triangle " + std::to_string(t)));
      }
    }
    return s;
  }

  Soup read_stl_ascii() const {
    Soup s;
    Merger merge;
    Lexer lex(data_);
    bool in_facet = false;
    int corners = 0;
    int facet_line = 0;
    std::array<int, 3> tri{};
    for (std::string_view tok = lex.next(); !tok.empty(); tok = lex.next()) {
      if (tok == "solid") {
        lex.skip_line();  // the solid's name
      } else if (tok == "facet") {
        if (in_facet) fail("line " + std::to_string(lex.line()) + ": 'facet' inside a facet (missing 'endfacet')");
        in_facet = true;
        corners = 0;
        facet_line = lex.line();
      } else if (tok == "vertex") {
        if (!in_facet) fail("line " + std::to_string(lex.line()) + ": 'vertex' outside a facet");
        double c[3];
        for (int d = 0; d < 3; ++d) c[d] = number(lex.next(), lex.line(), "a vertex coordinate");
        if (corners == 3)
          fail("facet at line " + std::to_string(facet_line) + " has more than 3 vertices (STL facets are triangles)");
        tri[corners++] = merge.index(s, *this, c[0], c[1], c[2], "line " + std::to_string(lex.line()));
      } else if (tok == "endfacet") {
        if (!in_facet) fail("line " + std::to_string(lex.line()) + ": 'endfacet' without 'facet'");
        if (corners != 3)
          fail("facet at line " + std::to_string(facet_line) + " has " + std::to_string(corners) +
               " vertices (STL facets are triangles)");
        s.tri.insert(s.tri.end(), tri.begin(), tri.end());
        in_facet = false;
      } else if (tok == "endsolid") {
        lex.skip_line();
      }
      // "normal" and its numbers, "outer", "loop" and "endloop" need nothing.
    }
    if (in_facet)
      fail("truncated: the file ends inside the facet that starts at line " + std::to_string(facet_line));
    return s;
  }

  Soup read_obj() const {
    Soup s;
    Lexer lex(data_, 0, '#');
    std::vector<std::string_view> tok;
    std::vector<long> poly;
    while (lex.next_line(tok)) {
      const int line = lex.current_line();
      const std::string where = "line " + std::to_string(line);
      if (tok[0] == "v") {
        if (tok.size() < 4) fail(where + ": vertex has fewer than 3 coordinates");
        // Values after x y z (w, or colours) are ignored.
        add_vertex(s, number(tok[1], line, "a coordinate"), number(tok[2], line, "a coordinate"),
                   number(tok[3], line, "a coordinate"), where);
      } else if (tok[0] == "f") {
        poly.clear();
        for (size_t k = 1; k < tok.size(); ++k) {
          // "i", "i/t", "i//n", "i/t/n": the vertex index is before the first '/'.
          std::string_view t = tok[k].substr(0, tok[k].find('/'));
          long idx;
          if (!parse_long(t, idx) || idx == 0)
            fail(where + ": bad vertex reference '" + std::string(tok[k]) + "' in a face");
          poly.push_back(idx > 0 ? idx - 1 : s.num_vertices() + idx);  // negative: relative to the end
          if (poly.back() < 0 || poly.back() > 2147483647L)
            fail(where + ": face refers to vertex " + std::string(t) + ", which does not exist");
        }
        add_polygon(s, poly, where);
      }
      // Other statements (vt, vn, g, o, s, usemtl, l, ...) do not change the surface.
    }
    return s;
  }

  Soup read_off() const {
    Soup s;
    Lexer lex(data_, 0, '#');
    std::vector<std::string_view> tok;
    lex.next_line(tok);
    const std::string header(tok[0]);
    if (header.find("4") != std::string::npos || header.find('n') != std::string::npos)
      fail("unsupported OFF variant '" + header + "' (only 3D OFF is read)");
    std::vector<std::string_view> counts(tok.begin() + 1, tok.end());
    if (counts.empty()) {
      if (!lex.next_line(tok)) fail("truncated: the file ends before the vertex and face counts");
      counts = tok;
    }
    long nv, nf;
    if (counts.size() < 2 || !parse_long(counts[0], nv) || !parse_long(counts[1], nf) || nv < 0 || nf < 0)
      fail("line " + std::to_string(lex.current_line()) + ": expected the vertex, face and edge counts");
    s.xyz.reserve(3 * static_cast<size_t>(std::min<long>(nv, static_cast<long>(data_.size() / 6))));  // a header can lie
    for (long i = 0; i < nv; ++i) {
      if (!lex.next_line(tok))
        fail("truncated: the header declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
             " faces, but the file ends after " + std::to_string(i) + " vertices");
      const int line = lex.current_line();
      if (tok.size() < 3) fail("line " + std::to_string(line) + ": vertex has fewer than 3 coordinates");
      add_vertex(s, number(tok[0], line, "a coordinate"), number(tok[1], line, "a coordinate"),
                 number(tok[2], line, "a coordinate"), "line " + std::to_string(line));
    }
    std::vector<long> poly;
    for (long f = 0; f < nf; ++f) {
      if (!lex.next_line(tok))
        fail("truncated: the header declares " + std::to_string(nf) + " faces, but the file ends after " +
             std::to_string(f) + " faces");
      const int line = lex.current_line();
      const std::string where = "line " + std::to_string(line);
      long n;
      if (!parse_long(tok[0], n) || n < 0) fail(where + ": expected the number of vertices of a face");
      if (static_cast<long>(tok.size()) < n + 1)
        fail(where + ": face declares " + std::to_string(n) + " vertices but lists " + std::to_string(tok.size() - 1));
      poly.clear();
      for (long k = 0; k < n; ++k) {
        long idx;
        if (!parse_long(tok[1 + k], idx)) fail(where + ": bad vertex index '" + std::string(tok[1 + k]) + "'");
        if (idx < 0 || idx >= nv)
          fail(where + ": face " + std::to_string(f) + " refers to vertex " + std::to_string(idx) +
               ", but the file has only " + std::to_string(nv) + " vertices");
        poly.push_back(idx);
      }
      add_polygon(s, poly, where);  // values after the indices (colours) are ignored
    }
    return s;
  }

  // ---- PLY ----
  enum class PlyType { I8, U8, I16, U16, I32, U32, F32, F64 };
  struct PlyProperty {
    std::string name;
    bool is_list = false;
    PlyType count_type = PlyType::U8, type = PlyType::F32;
  };
  struct PlyElement {
    std::string name;
    long count = 0;
    std::vector<PlyProperty> props;
  };

  PlyType ply_type(const std::string& t) const {
    if (t == "char" || t == "int8") return PlyType::I8;
    if (t == "uchar" || t == "uint8") return PlyType::U8;
    if (t == "short" || t == "int16") return PlyType::I16;
    if (t == "ushort" || t == "uint16") return PlyType::U16;
    if (t == "int" || t == "int32") return PlyType::I32;
    if (t == "uint" || t == "uint32") return PlyType::U32;
    if (t == "float" || t == "float32") return PlyType::F32;
    if (t == "double" || t == "float64") return PlyType::F64;
    fail("PLY header: unknown property type '" + t + "'");
  }
  static size_t ply_size(PlyType t) {
    switch (t) {
      case PlyType::I8: case PlyType::U8: return 1;
      case PlyType::I16: case PlyType::U16: return 2;
      case PlyType::I32: case PlyType::U32: case PlyType::F32: return 4;
      case PlyType::F64: return 8;
    }
    return 0;
  }

  // Reads one value, from text or from bytes (with the file's endianness).
  class PlyBody {
   public:
    PlyBody(const Reader& r, const std::string& data, size_t start, int format)
        : r_(r), data_(data), pos_(start), format_(format), lex_(data, start) {}
    double value(PlyType t, const std::string& what) {
      if (format_ == 0) {
        const std::string_view tok = lex_.next();
        if (tok.empty()) r_.fail("truncated: the file ends while reading " + what);
        double v;
        if (!parse_double(tok, v))
          r_.fail("line " + std::to_string(lex_.line()) + ": expected a number for " + what + ", found '" +
                  std::string(tok) + "'");
        return v;
      }
      const size_t n = ply_size(t);
      if (pos_ + n > data_.size()) r_.fail("truncated: the file ends while reading " + what);
      unsigned char b[8];
      std::memcpy(b, data_.data() + pos_, n);
      pos_ += n;
      const uint16_t probe = 1;
      unsigned char little;
      std::memcpy(&little, &probe, 1);
      const bool file_little = format_ == 1;
      if ((little == 1) != file_little) std::reverse(b, b + n);
      switch (t) {
        case PlyType::I8: { int8_t v; std::memcpy(&v, b, 1); return v; }
        case PlyType::U8: { uint8_t v; std::memcpy(&v, b, 1); return v; }
        case PlyType::I16: { int16_t v; std::memcpy(&v, b, 2); return v; }
        case PlyType::U16: { uint16_t v; std::memcpy(&v, b, 2); return v; }
        case PlyType::I32: { int32_t v; std::memcpy(&v, b, 4); return v; }
        case PlyType::U32: { uint32_t v; std::memcpy(&v, b, 4); return v; }
        case PlyType::F32: { float v; std::memcpy(&v, b, 4); return v; }
        case PlyType::F64: { double v; std::memcpy(&v, b, 8); return v; }
      }
      return 0;
    }

    bool ascii() const { return format_ == 0; }
    int line() const { return lex_.line(); }  // ASCII: the line of the last value

   private:
    const Reader& r_;
    const std::string& data_;
    size_t pos_;
    int format_;  // 0 ascii, 1 little endian, 2 big endian
    Lexer lex_;
  };

  Soup read_ply() const {
    const size_t end = data_.find("end_header");
    if (end == std::string::npos) fail("truncated PLY header: no 'end_header'");
    size_t start = data_.find('\n', end);
    start = start == std::string::npos ? data_.size() : start + 1;
    std::istringstream header(data_.substr(0, end));
    std::string line;
    int format = -1;
    std::vector<PlyElement> elements;
    std::getline(header, line);  // "ply"
    while (std::getline(header, line)) {
      std::istringstream ls(line);
      std::string kw;
      ls >> kw;
      if (kw == "format") {
        std::string f;
        ls >> f;
        if (f == "ascii") format = 0;
        else if (f == "binary_little_endian") format = 1;
        else if (f == "binary_big_endian") format = 2;
        else fail("PLY header: unknown format '" + f + "'");
      } else if (kw == "element") {
        PlyElement e;
        if (!(ls >> e.name >> e.count) || e.count < 0) fail("PLY header: bad element line '" + line + "'");
        elements.push_back(e);
      } else if (kw == "property") {
        if (elements.empty()) fail("PLY header: property before any element");
        PlyProperty p;
        std::string t;
        ls >> t;
        if (t == "list") {
          std::string ct, it;
          ls >> ct >> it;
          p.is_list = true;
          p.count_type = ply_type(ct);
          p.type = ply_type(it);
        } else {
          p.type = ply_type(t);
        }
        if (!(ls >> p.name)) fail("PLY header: bad property line '" + line + "'");
        elements.back().props.push_back(p);
      }
      // "comment" and "obj_info" lines carry nothing we need.
    }
    if (format < 0) fail("PLY header: no 'format' line");
    Soup s;
    PlyBody body(*this, data_, start, format);
    std::vector<long> poly;
    for (const PlyElement& e : elements) {
      const bool is_vertex = e.name == "vertex";
      const bool is_face = e.name == "face";
      int ix = -1, iy = -1, iz = -1, iface = -1;
      for (size_t k = 0; k < e.props.size(); ++k) {
        const auto& p = e.props[k];
        if (!p.is_list && p.name == "x") ix = static_cast<int>(k);
        if (!p.is_list && p.name == "y") iy = static_cast<int>(k);
        if (!p.is_list && p.name == "z") iz = static_cast<int>(k);
        if (p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index" || iface < 0))
          iface = static_cast<int>(k);
      }
      if (is_vertex && (ix < 0 || iy < 0 || iz < 0)) fail("PLY vertex element has no x, y and z properties");
      if (is_face && iface < 0) fail("PLY face element has no vertex_indices list");
      // An element without properties takes no bytes: counting through it
      // (the header may say 10^18 of them) would only spend time (found by
      // fuzzing).
      if (e.props.empty()) continue;
      for (long i = 0; i < e.count; ++i) {
        const std::string what = e.name + " " + std::to_string(i) + " of " + std::to_string(e.count);
        // ASCII PLY holds one element per line: a value on another line means
        // the header's counts do not match the body.
        int first_line = -1;
        auto value = [&](PlyType t) {
          const double v = body.value(t, what);
          if (body.ascii()) {
            if (first_line < 0) first_line = body.line();
            if (body.line() != first_line)
              fail("line " + std::to_string(first_line) + ": " + what + " continues onto line " +
                   std::to_string(body.line()) + " (one element per line): the header's element counts (" +
                   std::to_string(e.count) + " " + e.name + ") do not match the file");
          }
          return v;
        };
        double xyz[3] = {0, 0, 0};
        for (size_t k = 0; k < e.props.size(); ++k) {
          const auto& p = e.props[k];
          if (!p.is_list) {
            const double v = value(p.type);
            if (is_vertex) {
              if (static_cast<int>(k) == ix) xyz[0] = v;
              if (static_cast<int>(k) == iy) xyz[1] = v;
              if (static_cast<int>(k) == iz) xyz[2] = v;
            }
            continue;
          }
          const double cnt = value(p.count_type);
          // A count type may be float: beyond an int it is no length (and
          // would overflow the loop's counter; found by fuzzing).
          if (cnt < 0 || cnt != std::floor(cnt) || cnt > 2147483647.0) fail("bad list length in " + what);
          const bool keep = is_face && static_cast<int>(k) == iface;
          if (keep) poly.clear();
          for (long j = 0; j < static_cast<long>(cnt); ++j) {
            const double v = value(p.type);
            if (keep) {
              if (v < 0 || v != std::floor(v) || v > 2147483647.0) {
                char shown[32];
                std::snprintf(shown, sizeof shown, "%.10g", v);
                fail("face " + std::to_string(i) + ": its list of " + std::to_string(static_cast<long>(cnt)) +
                     " vertex indices holds " + shown +
                     ", which is no vertex index (a wrong list count or type in the header, or a corrupt file)");
              }
              poly.push_back(static_cast<long>(v));
            }
          }
          if (keep) add_polygon(s, poly, "face " + std::to_string(i));
        }
        if (is_vertex) add_vertex(s, xyz[0], xyz[1], xyz[2], "vertex element " + std::to_string(i));
      }
    }
    return s;
  }

  std::string path_;
  std::string data_;
};

}  // namespace

TriMesh read_surface(const std::string& path) {
  return Reader(path, read_input_file(path, "surface file")).read();
}

}  // namespace igaprep::mesh
