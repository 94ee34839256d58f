#include "config_text.hpp"

#include <sstream>

#include "pipeline/mode_name.hpp"
#include "spinhash/config_fields.h"

namespace spinhash::experiment {

std::string database_text(const MemoryDatabase& m) {
  const blob::Params& p = m.db.params();
  std::ostringstream s;
  s << p.model_count << " models, " << p.feature_count << " features, blob " << m.blob_bytes << " bytes ("
    << (p.feature_count ? static_cast<double>(m.blob_bytes) / p.feature_count : 0.0)
    << " B/feature); spin images " << p.bins_alpha << "x" << p.bins_beta << ", R = " << p.support_radius
    << " m, basis spacing " << p.basis_spacing << " m; LSH K = " << p.lsh_bits << ", L = " << p.lsh_tables
    << ", " << p.lsh_buckets << " buckets/table, largest bucket " << m.report.max_bucket << "; build "
    << m.build_seconds << " s";
  return s.str();
}

namespace {

void put(std::ostringstream& s, Mode v) { s << pipeline::mode_name(v); }
void put(std::ostringstream& s, bool v) { s << (v ? "on" : "off"); }
void put(std::ostringstream& s, uint32_t v) { s << v; }
void put(std::ostringstream& s, uint64_t v) { s << v; }
void put(std::ostringstream& s, float v) { s << v; }
void put(std::ostringstream& s, const double (&v)[3]) { s << v[0] << " " << v[1] << " " << v[2]; }

}  // namespace

// Every field of SPINHASH_CONFIG_FIELDS but the mode (the experiments list
// their modes), as "name value; ...".
std::string recognizer_text(const RecognizerConfig& c) {
  std::ostringstream s;
  const char* sep = "";
#define SPINHASH_PUT_FIELD(kind, name, lo, hi, flag, help) \
  if (std::string(#name) != "mode") {                      \
    s << sep << #name << " ";                              \
    put(s, c.name);                                        \
    sep = "; ";                                            \
  }
  SPINHASH_CONFIG_FIELDS(SPINHASH_PUT_FIELD)
#undef SPINHASH_PUT_FIELD
  return s.str();
}

}  // namespace spinhash::experiment
