#include "cloud/laz/item_codec.hpp"

#include "cloud/cloud_error.hpp"

namespace spinhash::host::laz {

void Median5::add(int32_t v) {
  int32_t* x = values_;
  if (high_) {
    if (v < x[2]) {
      x[4] = x[3];
      x[3] = x[2];
      if (v < x[0]) {
        x[2] = x[1];
        x[1] = x[0];
        x[0] = v;
      } else if (v < x[1]) {
        x[2] = x[1];
        x[1] = v;
      } else {
        x[2] = v;
      }
    } else {
      if (v < x[3]) {
        x[4] = x[3];
        x[3] = v;
      } else {
        x[4] = v;
      }
      high_ = false;
    }
    return;
  }
  if (x[2] < v) {
    x[0] = x[1];
    x[1] = x[2];
    if (x[4] < v) {
      x[2] = x[3];
      x[3] = x[4];
      x[4] = v;
    } else if (x[3] < v) {
      x[2] = x[3];
      x[3] = v;
    } else {
      x[2] = v;
    }
  } else {
    if (x[1] < v) {
      x[0] = x[1];
      x[1] = v;
    } else {
      x[0] = v;
    }
    high_ = true;
  }
}

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
