#include "json_reader.h"

#include "igaprep/core/error.h"

namespace igaprep::pipeline {

using nlohmann::json;

ObjectReader::ObjectReader(const json& object, std::string where, std::string file)
    : object_(object), where_(std::move(where)), file_(std::move(file)) {
  if (!object_.is_object()) fail(where_.empty() ? "the case must be a JSON object" : "'" + where_ + "' must be an object");
}

const json* ObjectReader::find(const std::string& key) {
  known_.insert(key);
  auto it = object_.find(key);
  return it == object_.end() ? nullptr : &*it;
}

double ObjectReader::number(const std::string& key, double fallback) {
  const json* v = find(key);
  if (!v) return fallback;
  if (!v->is_number()) fail("'" + path(key) + "' must be a number, got " + v->type_name());
  return v->get<double>();
}

double ObjectReader::number_in(const std::string& key, double fallback, double lo, double hi) {
  if (!object_.contains(key)) return number(key, fallback);  // marks it known; the default is not checked
  const double x = number(key, fallback);
  if (!(x >= lo && x <= hi))
    fail("'" + path(key) + "' must be a number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return x;
}

double ObjectReader::required_number(const std::string& key) {
  if (!object_.contains(key)) fail("missing key '" + path(key) + "'");
  return number(key, 0.0);
}

int ObjectReader::integer(const std::string& key, int fallback, int lo, int hi) {
  const json* v = find(key);
  if (!v) return fallback;
  if (!v->is_number_integer()) fail("'" + path(key) + "' must be an integer, got " + v->type_name());
  const long long x = v->get<long long>();
  if (x < lo || x > hi)
    fail("'" + path(key) + "' must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
         std::to_string(x));
  return static_cast<int>(x);
}

bool ObjectReader::boolean(const std::string& key, bool fallback) {
  const json* v = find(key);
  if (!v) return fallback;
  if (!v->is_boolean()) fail("'" + path(key) + "' must be true or false, got " + v->type_name());
  return v->get<bool>();
}

std::string ObjectReader::string(const std::string& key, const std::string& fallback) {
  const json* v = find(key);
  if (!v) return fallback;
  if (!v->is_string()) fail("'" + path(key) + "' must be a string, got " + v->type_name());
  return v->get<std::string>();
}

std::string ObjectReader::path(const std::string& key) const { return where_.empty() ? key : where_ + "." + key; }

void ObjectReader::refuse_unknown() const {
  for (auto it = object_.begin(); it != object_.end(); ++it) {
    if (known_.count(it.key())) continue;
    std::string list;
    for (const auto& k : known_) list += (list.empty() ? "" : ", ") + k;
    fail("unknown key '" + path(it.key()) + "' (known here: " + list + ")");
  }
}

void ObjectReader::fail(const std::string& message) const { throw bad_input(file_ + ": " + message); }

Eigen::Vector3d read_vector3(const json& v, const std::string& where, const std::string& file) {
  if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
    throw bad_input(file + ": '" + where + "' must be a list of three numbers");
  const Eigen::Vector3d x(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
  if (!x.allFinite()) throw bad_input(file + ": '" + where + "' must be finite");
  return x;
}

}  // namespace igaprep::pipeline
