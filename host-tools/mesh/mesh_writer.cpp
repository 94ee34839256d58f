#include "mesh/mesh_writer.hpp"

#include "blob/file_io.hpp"

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>

namespace spinhash::host {
namespace {

// %.9g round-trips every float exactly.
constexpr const char* kObjVertexFormat = "v %.9g %.9g %.9g\n";
constexpr std::size_t kLineBufferBytes = 128;
constexpr uint8_t kCornersPerFace = 3;

void append_le32(std::string* out, uint32_t bits) {
  for (int shift = 0; shift < 32; shift += 8) out->push_back(static_cast<char>(bits >> shift));
}

void append_float_le(std::string* out, float value) {
  uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  append_le32(out, bits);
}

// Names go into one header line: keep them printable and free of spaces.
std::string header_name(const std::string& name) {
  std::string safe = name.empty() ? "mesh" : name;
  for (char& c : safe) {
    if (c <= ' ' || c > '~') c = '_';
  }
  return safe;
}

std::string obj_text(const Mesh& mesh) {
  std::string text = "# spinhash mesh\no " + header_name(mesh.name) + "\n";
  char line[kLineBufferBytes];
  for (std::size_t i = 0; i < mesh.vertex_count(); ++i) {
    std::snprintf(line, sizeof line, kObjVertexFormat, mesh.vertices[3 * i], mesh.vertices[3 * i + 1],
                  mesh.vertices[3 * i + 2]);
    text += line;
  }
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    // OBJ indices are 1-based.
    std::snprintf(line, sizeof line, "f %u %u %u\n", mesh.triangles[3 * t] + 1, mesh.triangles[3 * t + 1] + 1,
                  mesh.triangles[3 * t + 2] + 1);
    text += line;
  }
  return text;
}

std::string ply_bytes(const Mesh& mesh) {
  std::string bytes = "ply\nformat binary_little_endian 1.0\ncomment spinhash mesh " +
                      header_name(mesh.name) + "\nelement vertex " + std::to_string(mesh.vertex_count()) +
                      "\nproperty float x\nproperty float y\nproperty float z\n"
                      "element face " +
                      std::to_string(mesh.triangle_count()) +
                      "\nproperty list uchar uint vertex_indices\nend_header\n";
  for (float v : mesh.vertices) append_float_le(&bytes, v);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    bytes.push_back(static_cast<char>(kCornersPerFace));
    for (int k = 0; k < 3; ++k) append_le32(&bytes, mesh.triangles[3 * t + k]);
  }
  return bytes;
}

template <typename Encode>
bool write_encoded(const std::string& path, const Mesh& mesh, Encode encode, std::string* error) {
  const std::string problem = mesh.validate();
  if (!problem.empty()) {
    if (error) *error = "cannot write " + path + ": " + problem;
    return false;
  }
  try {
    const std::string bytes = encode(mesh);
    return write_file_atomically(path, bytes.data(), bytes.size(), error);
  } catch (const std::exception& e) {
    if (error) *error = "cannot write " + path + ": " + e.what();
    return false;
  }
}

}  // namespace

bool write_obj(const std::string& path, const Mesh& mesh, std::string* error) {
  return write_encoded(path, mesh, obj_text, error);
}

bool write_mesh_ply(const std::string& path, const Mesh& mesh, std::string* error) {
  return write_encoded(path, mesh, ply_bytes, error);
}

bool write_mesh(const std::string& path, const Mesh& mesh, std::string* error) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".obj") return write_obj(path, mesh, error);
  if (extension == ".ply") return write_mesh_ply(path, mesh, error);
  if (error) *error = "cannot write " + path + ": unknown mesh extension (use .obj or .ply)";
  return false;
}

}  // namespace spinhash::host
