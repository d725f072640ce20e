#include "hdf5_writer.h"

namespace igaprep::exporter::detail {

void write_materials(const Hdf5Writer& w, hid_t root, const std::vector<spline::Material>& materials) {
  H5Handle mats = w.create_group(root, "materials", "group /materials");
  std::vector<std::string> names;
  std::vector<double> young, poisson;
  for (const spline::Material& m : materials) {
    names.push_back(m.name);
    young.push_back(m.young_modulus);
    poisson.push_back(m.poisson_ratio);
  }
  const std::vector<hsize_t> nm = {static_cast<hsize_t>(materials.size())};
  w.write_strings(mats.get(), "name", "dataset /materials/name", names);
  w.write_dataset(mats.get(), "young_modulus", "dataset /materials/young_modulus", H5T_IEEE_F64LE,
                  H5T_NATIVE_DOUBLE, nm, young.data());
  w.write_dataset(mats.get(), "poisson_ratio", "dataset /materials/poisson_ratio", H5T_IEEE_F64LE,
                  H5T_NATIVE_DOUBLE, nm, poisson.data());
}

void write_provenance(const Hdf5Writer& w, hid_t root, const std::string& generator, const std::string& case_json,
                      const std::string& inputs) {
  if (generator.empty() && case_json.empty() && inputs.empty()) return;
  H5Handle prov = w.create_group(root, "provenance", "group /provenance");
  w.string_attribute(prov.get(), "generator", "attribute /provenance/generator", generator);
  w.string_attribute(prov.get(), "case", "attribute /provenance/case", case_json);
  w.string_attribute(prov.get(), "inputs", "attribute /provenance/inputs", inputs);
}

}  // namespace igaprep::exporter::detail
