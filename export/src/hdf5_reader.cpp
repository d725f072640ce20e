#include "hdf5_reader.h"

namespace igaprep::exporter::detail {

void expect_format(const Hdf5Reader& r, const std::string& format) {
  const hid_t root = r.root();
  if (!r.has_attribute(root, "format")) r.bad("attribute /format", "missing: not an igaprep model file");
  const std::string found = r.string_scalar(root, "format", "/format");
  if (found != format) r.bad("attribute /format", "is '" + found + "', expected '" + format + "'");
  const int version = r.int_scalar(root, "format_version", "/format_version");
  if (version != 1)
    r.bad("attribute /format_version", "version " + std::to_string(version) + " is not supported (this igaprep reads version 1)");
}

std::vector<spline::Material> read_materials(const Hdf5Reader& r) {
  H5Handle mats = r.open_group(r.root(), "materials", "/materials");
  const std::vector<std::string> names = r.read_strings(mats.get(), "name", "/materials/name");
  std::vector<hsize_t> dy, dp;
  const std::vector<double> young = r.read_doubles(mats.get(), "young_modulus", "/materials/young_modulus", &dy);
  const std::vector<double> poisson = r.read_doubles(mats.get(), "poisson_ratio", "/materials/poisson_ratio", &dp);
  r.expect_rank(dy, 1, "dataset /materials/young_modulus", "(" + std::to_string(names.size()) + ",)");
  r.expect_rank(dp, 1, "dataset /materials/poisson_ratio", "(" + std::to_string(names.size()) + ",)");
  if (young.size() != names.size())
    r.bad("dataset /materials/young_modulus", std::to_string(young.size()) + " entries but /materials/name has " + std::to_string(names.size()));
  if (poisson.size() != names.size())
    r.bad("dataset /materials/poisson_ratio", std::to_string(poisson.size()) + " entries but /materials/name has " + std::to_string(names.size()));
  std::vector<spline::Material> out;
  for (size_t m = 0; m < names.size(); ++m) out.push_back({names[m], young[m], poisson[m]});
  return out;
}

void read_provenance(const Hdf5Reader& r, std::string* generator, std::string* case_json, std::string* inputs) {
  if (!r.has_link(r.root(), "provenance")) return;
  H5Handle prov = r.open_group(r.root(), "provenance", "/provenance");
  if (r.has_attribute(prov.get(), "generator")) *generator = r.string_scalar(prov.get(), "generator", "/provenance/generator");
  if (r.has_attribute(prov.get(), "case")) *case_json = r.string_scalar(prov.get(), "case", "/provenance/case");
  if (r.has_attribute(prov.get(), "inputs")) *inputs = r.string_scalar(prov.get(), "inputs", "/provenance/inputs");
}

}  // namespace igaprep::exporter::detail
