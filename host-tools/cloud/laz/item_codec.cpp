#include "cloud/laz/item_codec.hpp"

#include "cloud/cloud_error.hpp"

namespace spinhash::host::laz {

std::unique_ptr<PointwiseItem> make_pointwise_item(const LazItem& item) {
  switch (item.type) {
    case ItemType::kPoint10: return make_point10(item.version);
    case ItemType::kGpsTime11: return make_gpstime11(item.version);
    case ItemType::kRgb12: return make_rgb12(item.version);
    case ItemType::kByte: return make_byte(item.version, item.size);
    default: throw CloudError("LAZ: item " + item_name(item.type) + " cannot be decoded pointwise");
  }
}

std::unique_ptr<LayeredItem> make_layered_item(const LazItem& item) {
  switch (item.type) {
    case ItemType::kPoint14: return make_point14(item.version);
    case ItemType::kRgb14: return make_rgb14(item.version, false);
    case ItemType::kRgbNir14: return make_rgb14(item.version, true);
    case ItemType::kByte14: return make_byte14(item.version, item.size);
    default: throw CloudError("LAZ: item " + item_name(item.type) + " cannot be decoded in layers");
  }
}

}  // namespace spinhash::host::laz
