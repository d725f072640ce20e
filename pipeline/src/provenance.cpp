#include "igaprep/pipeline/provenance.h"

#include <openssl/evp.h>

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <memory>
#include <vector>

#include <nlohmann/json.hpp>

#include "igaprep/core/error.h"
#include "igaprep/pipeline/run.h"
#include "version.h"

namespace igaprep::pipeline {

std::string generator_name() {
  return std::string("igaprep ") + IGAPREP_VERSION_STRING + " (git " + IGAPREP_GIT_REVISION + ")";
}

std::string sha256_of_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw bad_input("cannot read '" + path + "' to hash it");
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx(EVP_MD_CTX_new(), EVP_MD_CTX_free);
  if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1) throw internal_error("SHA-256: no context");
  std::vector<char> buffer(1 << 16);
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    if (in.gcount() > 0) EVP_DigestUpdate(ctx.get(), buffer.data(), static_cast<std::size_t>(in.gcount()));
  }
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  EVP_DigestFinal_ex(ctx.get(), digest, &length);
  std::string hex;
  char byte[3];
  for (unsigned int i = 0; i < length; ++i) {
    std::snprintf(byte, sizeof byte, "%02x", digest[i]);
    hex += byte;
  }
  return hex;
}

std::string run_date_utc() {
  std::time_t t = std::time(nullptr);
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) t = static_cast<std::time_t>(std::strtoll(epoch, nullptr, 10));
  std::tm utc{};
  gmtime_r(&t, &utc);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return buf;
}

void stamp_report(iga_check::CheckReport& report) {
  report.generator = generator_name();
  report.date = run_date_utc();
}

void fill_provenance(const Case& c, spline::MultiPatch& model) {
  using nlohmann::json;
  json surfaces = json::array();
  for (const auto& s : c.surfaces) {
    json e{{"label", s.label}};
    if (!s.file.empty()) {
      e["file"] = s.file;
      e["sha256"] = sha256_of_file(s.file);
    } else if (s.offset_of) {
      e["offset_of"] = *s.offset_of;
      e["inward"] = s.inward;
    } else {
      e["built_in"] = c.name;
    }
    surfaces.push_back(e);
  }
  const json inputs{{"case_file", c.path},
                    {"surfaces", surfaces},
                    {"options", json::parse(case_json(c, "", true))},
                    {"date", run_date_utc()}};
  model.provenance_generator = generator_name();
  model.provenance_case = c.text.empty() ? case_json(c, "", true) : c.text;
  model.provenance_inputs = inputs.dump(2);
}

}  // namespace igaprep::pipeline
