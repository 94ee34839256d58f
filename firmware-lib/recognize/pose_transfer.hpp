// The transfer stage (not in the paper; BRAN; stage_fields.h:
// TransferParams): look-alike pose transfer. In a database with many
// look-alikes, the W candidates of a query feature are shared among them, so
// the true model may get no correct doublet while a look-alike's pose fits
// it within Delta. The best poses found (of transfer_poses leading models)
// are therefore also verified, through the same likelihood, on the
// transfer_models models whose bounding boxes (each in its own frame) are
// nearest the posed model's; the least-squares refinement of the leading
// models then settles the fit. A model in another frame convention just
// scores badly at a lent pose and changes nothing; it is dropped after a few
// dozen features when clearly worse than the pose's source (the preemptive
// checks of verify_pose). Bounded: kMaxTransferPoses x kMaxTransferModels
// extra verifications, after the hypothesis budget (counted in
// TransferStats::transferred); none begins once the query has spent its
// work cap (work_meter.hpp).
#pragma once
#include "recognize/search_context.hpp"

namespace spinhash {

Status transfer_stage(SearchContext& ctx);

}  // namespace spinhash
