#pragma once
// Reads the keys of one JSON object of a case file and refuses any it does
// not know; every failure is bad_input naming the file and the key's path.
#include <set>
#include <string>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace igaprep::pipeline {

class ObjectReader {
 public:
  // `where`: the object's path in the case ("" for the root, "fit", ...).
  ObjectReader(const nlohmann::json& object, std::string where, std::string file);

  // The value of `key` or nullptr; marks the key as known either way.
  const nlohmann::json* find(const std::string& key);
  double number(const std::string& key, double fallback);
  // A value given must lie in [lo, hi]; the fallback is not checked.
  double number_in(const std::string& key, double fallback, double lo, double hi);
  double required_number(const std::string& key);
  int integer(const std::string& key, int fallback, int lo, int hi);
  bool boolean(const std::string& key, bool fallback);
  std::string string(const std::string& key, const std::string& fallback);
  // "a.b" for key b of object a.
  std::string path(const std::string& key) const;
  // Call after reading every key: any other key is an error.
  void refuse_unknown() const;
  [[noreturn]] void fail(const std::string& message) const;
  const std::string& file() const { return file_; }

 private:
  const nlohmann::json& object_;
  std::string where_;
  std::string file_;
  std::set<std::string> known_;
};

// [x, y, z], finite; bad_input naming `where` otherwise.
Eigen::Vector3d read_vector3(const nlohmann::json& v, const std::string& where, const std::string& file);

}  // namespace igaprep::pipeline
