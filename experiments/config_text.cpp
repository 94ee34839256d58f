#include "config_text.hpp"

#include <sstream>

#include "config/config_text.hpp"

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

// Every field of the field lists but the mode (the experiments list their
// modes), as "key value; ...".
std::string recognizer_text(const RecognizerConfig& c) { return host::config_text(c, false); }

}  // namespace spinhash::experiment
