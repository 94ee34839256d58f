// What a point-cloud file is, from its first bytes: the one place that
// recognises LAS/LAZ, PLY and the compressed or foreign formats this reader
// refuses (gzip, zip, E57, PCD) with how to convert them.
#pragma once

#include <string>

namespace spinhash::host {

enum class CloudFormat { kLas, kPly, kText, kForeign };

// Enough leading bytes to tell every format apart.
constexpr size_t kSniffBytes = 16;

CloudFormat sniff_cloud_format(const std::string& head);

// True when bytes begin with the LAS signature "LASF" (LAS and LAZ).
bool is_las(const std::string& bytes);
bool is_ply(const std::string& bytes);

// A message naming a compressed or foreign format recognised by its first
// bytes, with how to convert it; empty when none is recognised. (LAZ is LAS
// with compressed points: the LAS reader decodes it.)
std::string foreign_cloud_format(const std::string& bytes);

}  // namespace spinhash::host
