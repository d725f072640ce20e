#pragma once
// M, H and the w-field of a built-in model, built once per test process on top
// of the cached midsurface (test_midsurface_cache.h), for the decomposition
// tests.
#include <map>
#include <memory>
#include <string>

#include "igaprep/param/base_surface.h"
#include "igaprep/param/decomposition_mesh.h"
#include "igaprep/param/w_field.h"
#include "test_midsurface_cache.h"

namespace decomposition_test {

struct Case {
  const midsurface_test::Case* mid = nullptr;
  igaprep::param::BaseSurface base;  // M as the run makes it (default options)
  igaprep::param::DecompositionMesh H;
  igaprep::param::WField w;  // empty until with_w()
};

inline Case& cached(const std::string& name, bool with_w = true) {
  static std::map<std::string, std::unique_ptr<Case>> cache;
  auto& slot = cache[name];
  if (!slot) {
    slot = std::make_unique<Case>();
    slot->mid = &midsurface_test::cached(name);
    slot->base = igaprep::param::base_surface(slot->mid->result.m0trim.mesh, slot->mid->result.polycube, {});
    slot->H = igaprep::param::decomposition_mesh(slot->mid->model.surfaces, slot->base.m.mesh);
  }
  if (with_w && slot->w.w.size() == 0) slot->w = igaprep::param::w_field(slot->H);
  return *slot;
}

}  // namespace decomposition_test
