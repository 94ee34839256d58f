#include "config_text.hpp"

#include <sstream>

namespace spinhash::experiment {

std::string database_text(const MemoryDatabase& m) {
  const blob::Params& p = m.db.params();
  std::ostringstream s;
  s << p.model_count << " models, " << p.feature_count << " features, blob " << m.blob_bytes << " bytes ("
    << (p.feature_count ? static_cast<double>(m.blob_bytes) / p.feature_count : 0.0) << " B/feature); spin images "
    << p.bins_alpha << "x" << p.bins_beta << ", R = " << p.support_radius << " m, basis spacing "
    << p.basis_spacing << " m; LSH K = " << p.lsh_bits << ", L = " << p.lsh_tables << ", " << p.lsh_buckets
    << " buckets/table, largest bucket " << m.report.max_bucket << "; build " << m.build_seconds << " s";
  return s.str();
}

std::string recognizer_text(const RecognizerConfig& c) {
  std::ostringstream s;
  s << "W = " << c.top_w << " (BRAN), " << c.top_w_sran << " (SRAN), " << c.top_w_sind
    << " (SIND); trials " << c.max_trials << " (BRAN), " << c.sran_trials << " per model (SRAN); max hypotheses "
    << c.max_hypotheses << "; max bucket scan " << c.max_bucket_scan << "; max features " << c.max_features
    << "; look-alike pose transfer " << c.transfer_models << " models per leading pose (BRAN; 0: the paper's BRAN)"
    << "; seed " << c.seed;
  return s.str();
}

}  // namespace spinhash::experiment
