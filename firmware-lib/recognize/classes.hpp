// The classes stage (not in the paper; stage_fields.h: ClassesParams): the
// level an answer can give when the scan does not tell one model from
// another ("a pickup", not which). The classes of the ranked models, each
// scored by its best model, and whether the first is named confidently.
#pragma once
#include <cstdint>

#include "recognize/confidence.hpp"
#include "recognize/search_context.hpp"

namespace spinhash {

Status classes_stage(SearchContext& ctx);

// The classes of r's ranking, each scored by its first model in the ranking
// (its best but for the twins order_twins_by_residuals swaps), best first
// (ties by class id); returns how many (at most kVehicleClassCount).
uint32_t rank_classes(const Database& db, const Result& r, RankedClass* out);

// The first class stands alone: its best model explains the query as
// is_confident() asks (min_inlier_fraction, min_mean_log_likelihood), the
// scan does not stop short of or reach beyond that model's box by more than
// class_extent_factor times what `confident` allows (`fit`: members of a
// class differ by tens of centimetres, a vehicle of another class by
// metres, and without the shortfall test a bus explains every point of a
// van's sparse scan), the next class scores at least min_margin x
// sqrt(features) lower, the database holds a second class to tell it from,
// the class is not "unclassified", and the scan is dense enough
// (min_class_density) with min_class_features. The stage then also asks the
// scan's shape to lie within the class's envelope (class_envelope.hpp).
bool is_class_confident(const Result& r, const RecognizerConfig& cfg, uint32_t features, const ExtentFit& fit,
                        float density);

// The tests is_class_confident() asks of the first class's best model but
// the class's own (its margin, not unclassified), asked of ranked model `m`
// under its extent fit `fit` and the scan's density under it: what the
// group level asks of the member that speaks for the group.
bool model_explains_scan(const Result& r, const RecognizerConfig& cfg, uint32_t features,
                         const RankedModel& m, const ExtentFit& fit, float density);

}  // namespace spinhash
