// Variable-length records of a LAS file: the VLRs between the header and
// the points, and LAS 1.4's extended VLRs after them. Only the records a
// reader needs are kept in memory (the CRS and LASzip records); the rest are
// listed without their payload.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cloud/byte_source.hpp"
#include "cloud/las_header.hpp"

namespace spinhash::host {

constexpr const char* kLasProjectionUserId = "LASF_Projection";
constexpr uint16_t kGeoKeyDirectoryRecord = 34735;
constexpr uint16_t kGeoDoubleParamsRecord = 34736;
constexpr uint16_t kGeoAsciiParamsRecord = 34737;
constexpr uint16_t kOgcWktRecord = 2112;
// liblas and PDAL's older writers also store the WKT under this user id
// (same record id): read when the file's GeoKeys do not name the CRS.
constexpr const char* kLiblasUserId = "liblas";
// An extended VLR payload above this is not loaded (waveforms, COPC
// hierarchies): its header is listed, its bytes skipped.
constexpr uint64_t kMaxLoadedVlrBytes = uint64_t{1} << 20;

struct Vlr {
  std::string user_id;
  uint16_t record_id = 0;
  uint64_t length = 0;    // payload bytes as declared
  bool extended = false;  // an EVLR
  bool loaded = false;    // data holds the payload
  std::vector<uint8_t> data;
};

// The VLRs and EVLRs of the file whose header is h. A record count that
// runs past the point data (a common writer bug) ends the list with a
// warning, as the offset to the points decides where they start.
std::vector<Vlr> read_vlrs(ByteSource& src, const LasHeader& h, std::vector<std::string>* warnings);

// The first loaded record with this user id and record id, or nullptr.
const Vlr* find_vlr(const std::vector<Vlr>& vlrs, const std::string& user_id, uint16_t record_id);

}  // namespace spinhash::host
