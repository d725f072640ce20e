#include "igaprep/export/export_model.h"

#include <algorithm>
#include <filesystem>
#include <memory>

#include "igaprep/core/atomic_file.h"
#include "igaprep/core/error.h"
#include "igaprep/export/bext.h"
#include "igaprep/export/gismo_xml.h"
#include "igaprep/export/hdf5_model.h"
#include "igaprep/export/mfem_mesh.h"
#include "igaprep/export/vtu_bezier.h"
#include "igaprep/export/vtu_boundary.h"
#include "model_checks.h"

namespace igaprep::exporter {

namespace {
constexpr Format kAll[] = {Format::Hdf5, Format::Gismo, Format::Mfem, Format::Vtu, Format::Bext};
}

std::string format_name(Format f) {
  switch (f) {
    case Format::Hdf5: return "hdf5";
    case Format::Gismo: return "gismo";
    case Format::Mfem: return "mfem";
    case Format::Vtu: return "vtu";
    case Format::Bext: return "bext";
  }
  return "?";
}

std::string format_extension(Format f) {
  switch (f) {
    case Format::Hdf5: return ".h5";
    case Format::Gismo: return ".xml";
    case Format::Mfem: return ".mesh";
    case Format::Vtu: return ".vtu";
    case Format::Bext: return ".k";
  }
  return "";
}

std::vector<Format> parse_formats(const std::string& list) {
  std::vector<Format> out;
  size_t start = 0;
  while (start <= list.size()) {
    size_t end = list.find(',', start);
    if (end == std::string::npos) end = list.size();
    std::string word = list.substr(start, end - start);
    word.erase(0, word.find_first_not_of(" \t"));
    word.erase(word.find_last_not_of(" \t") + 1);
    start = end + 1;
    if (word.empty()) continue;
    std::string lower = word;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
    bool found = false;
    for (Format f : kAll)
      if (format_name(f) == lower) {
        if (std::find(out.begin(), out.end(), f) == out.end()) out.push_back(f);
        found = true;
      }
    if (!found) throw bad_input("unknown export format '" + word + "' (known: hdf5, gismo, mfem, vtu, bext)");
  }
  if (out.empty()) throw bad_input("no export format given (known: hdf5, gismo, mfem, vtu, bext)");
  return out;
}

std::vector<std::string> format_paths(const std::string& basename, Format f, int materials) {
  if (f == Format::Vtu) return {basename + ".vtu", basename + "_boundary.vtu"};
  if (f == Format::Bext) return bext_paths(basename, materials);
  return {basename + format_extension(f)};
}

std::vector<std::string> export_model(const spline::MultiPatch& model, const std::string& basename,
                                      const std::vector<Format>& formats, const VtuOptions& vtu,
                                      const ProgressCallback& progress) {
  detail::check_model_for_writing(model, "'" + basename + "'");
  // Every format into its temporary file first, then all renamed into place:
  // a format that fails leaves none of them (and the previous files) behind.
  std::vector<std::unique_ptr<AtomicPath>> targets;
  for (const Format& f : formats) {
    const std::vector<std::string> paths = format_paths(basename, f, static_cast<int>(model.materials.size()));
    targets.push_back(std::make_unique<AtomicPath>(paths.front()));
    AtomicPath& t = *targets.back();
    if (f == Format::Vtu) {  // the labelled boundary beside the model
      targets.push_back(std::make_unique<AtomicPath>(paths.back()));
      targets.back()->write([&](std::ostream& out) { write_vtu_boundary(model, out); }, true);
    }
    std::vector<std::string> part_files;  // bext: the deck names them relative to itself
    for (std::size_t m = 1; f == Format::Bext && m < paths.size(); ++m) {
      part_files.push_back(std::filesystem::path(paths[m]).filename().string());
      targets.push_back(std::make_unique<AtomicPath>(paths[m]));
      targets.back()->write([&](std::ostream& out) { write_bext_part(model, static_cast<int>(m) - 1, out); });
    }
    switch (f) {
      case Format::Hdf5: write_hdf5_model(model, t); break;
      case Format::Gismo: t.write([&](std::ostream& out) { write_gismo_xml(model, out); }); break;
      case Format::Mfem: t.write([&](std::ostream& out) { write_mfem_mesh(model, out); }); break;
      case Format::Vtu: t.write([&](std::ostream& out) { write_vtu_bezier(model, out, vtu); }, true); break;
      case Format::Bext: t.write([&](std::ostream& out) { write_lsdyna_deck(model, part_files, out); }); break;
    }
    if (progress) progress("export", static_cast<std::size_t>(&f - formats.data()) + 1, formats.size());
  }
  std::vector<std::string> written;
  for (auto& t : targets) {
    t->commit();
    written.push_back(t->path());
  }
  return written;
}

std::vector<std::string> extraction_format_paths(const std::string& basename, Format f, int materials) {
  if (f == Format::Vtu) return {basename + ".vtu"};
  if (f == Format::Bext) return bext_paths(basename, materials);
  throw bad_input("'" + basename + "': a Bezier-extraction model is written as vtu or bext, not " + format_name(f));
}

std::vector<std::string> export_extraction_model(const spline::ExtractionModel& model, const std::string& basename,
                                                 const std::vector<Format>& formats) {
  const int materials = static_cast<int>(model.materials.size());
  for (const Format f : formats) extraction_format_paths(basename, f, materials);  // refused before writing
  std::vector<std::unique_ptr<AtomicPath>> targets;
  for (const Format f : formats) {
    const std::vector<std::string> paths = extraction_format_paths(basename, f, materials);
    if (f == Format::Vtu) {
      targets.push_back(std::make_unique<AtomicPath>(paths.front()));
      targets.back()->write([&](std::ostream& out) { write_vtu_bezier(model, out); }, true);
      continue;
    }
    std::vector<std::string> part_files;  // the deck names them relative to itself
    for (std::size_t m = 1; m < paths.size(); ++m) {
      part_files.push_back(std::filesystem::path(paths[m]).filename().string());
      targets.push_back(std::make_unique<AtomicPath>(paths[m]));
      targets.back()->write([&](std::ostream& out) { write_bext_part(model, static_cast<int>(m) - 1, out); });
    }
    targets.push_back(std::make_unique<AtomicPath>(paths.front()));
    targets.back()->write([&](std::ostream& out) { write_lsdyna_deck(model, part_files, out); });
  }
  std::vector<std::string> written;
  for (auto& t : targets) {
    t->commit();
    written.push_back(t->path());
  }
  return written;
}

}  // namespace igaprep::exporter
