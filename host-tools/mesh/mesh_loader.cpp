#include "mesh/mesh_loader.hpp"

#include "mesh/ply_mesh_reader.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <exception>
#include <filesystem>
#include <limits>
#include <system_error>
#include <unordered_map>

namespace spinhash::host {
namespace {

namespace fs = std::filesystem;

constexpr unsigned kImportFlags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                  aiProcess_PreTransformVertices | aiProcess_ValidateDataStructure;
constexpr unsigned kTriangleCorners = 3;
// Total area below this (m^2) means every triangle is degenerate.
constexpr double kMinSurfaceArea = 1e-12;

void set_error(std::string* error, const std::string& message) {
  if (error) *error = message;
}

// Appends the triangles of one aiMesh, copying only the vertices they use.
bool append_triangles(const aiMesh& source, Mesh* out, std::string* error) {
  std::unordered_map<unsigned, uint32_t> remap;
  for (unsigned f = 0; f < source.mNumFaces; ++f) {
    const aiFace& face = source.mFaces[f];
    if (face.mNumIndices != kTriangleCorners) continue;  // points and lines
    uint32_t corners[kTriangleCorners];
    for (unsigned k = 0; k < kTriangleCorners; ++k) {
      const unsigned index = face.mIndices[k];
      if (index >= source.mNumVertices) {
        set_error(error, "face index out of range");
        return false;
      }
      auto found = remap.find(index);
      if (found == remap.end()) {
        const aiVector3D& v = source.mVertices[index];
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
          set_error(error, "non-finite vertex coordinate");
          return false;
        }
        if (out->vertex_count() >= std::numeric_limits<uint32_t>::max()) {
          set_error(error, "too many vertices");
          return false;
        }
        found = remap.emplace(index, out->add_vertex({v.x, v.y, v.z})).first;
      }
      corners[k] = found->second;
    }
    out->add_triangle(corners[0], corners[1], corners[2]);
  }
  return true;
}

bool is_ply(const std::string& path) {
  std::string extension = fs::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".ply";
}

// Every mesh of the scene, node transforms applied, triangulated and merged.
bool load_with_assimp(const std::string& path, Mesh* mesh, std::string* error) {
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, kImportFlags);
  if (scene == nullptr) {
    set_error(error, "cannot read mesh " + path + ": " + importer.GetErrorString());
    return false;
  }
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    if (scene->mMeshes[m] == nullptr) continue;
    std::string part_error;
    if (!append_triangles(*scene->mMeshes[m], mesh, &part_error)) {
      set_error(error, "invalid mesh " + path + ": " + part_error);
      return false;
    }
  }
  return true;
}

bool load_scene(const std::string& path, Mesh* out, std::string* error) {
  std::error_code ec;
  if (!fs::exists(path, ec)) {
    set_error(error, "file not found: " + path);
    return false;
  }
  if (fs::is_directory(path, ec)) {
    set_error(error, "is a directory, not a mesh file: " + path);
    return false;
  }
  Mesh mesh;
  if (is_ply(path) ? !read_ply_mesh(path, &mesh, error) : !load_with_assimp(path, &mesh, error)) return false;
  mesh.name = fs::path(path).stem().string();
  if (mesh.triangle_count() == 0) {
    set_error(error, "no triangles in " + path);
    return false;
  }
  if (!(mesh.surface_area() > kMinSurfaceArea)) {
    set_error(error, "degenerate mesh (zero surface area) in " + path);
    return false;
  }
  *out = std::move(mesh);
  return true;
}

bool is_hidden(const fs::path& path) {
  const std::string name = path.filename().string();
  return !name.empty() && name[0] == '.';
}

}  // namespace

bool load_mesh(const std::string& path, Mesh* out, std::string* error) {
  if (out == nullptr) {
    set_error(error, "load_mesh: null output");
    return false;
  }
  try {
    return load_scene(path, out, error);
  } catch (const std::exception& e) {
    set_error(error, "cannot read mesh " + path + ": " + e.what());
  } catch (...) {
    set_error(error, "cannot read mesh " + path + ": unknown failure");
  }
  return false;
}

std::vector<std::string> list_mesh_files(const std::string& path_or_dir, std::string* error) {
  std::vector<std::string> files;
  try {
    std::error_code ec;
    if (!fs::exists(path_or_dir, ec)) {
      set_error(error, "path not found: " + path_or_dir);
      return files;
    }
    if (!fs::is_directory(path_or_dir, ec)) {
      files.push_back(path_or_dir);
      return files;
    }
    Assimp::Importer importer;
    for (const fs::directory_entry& entry : fs::directory_iterator(path_or_dir, ec)) {
      const fs::path& path = entry.path();
      if (!entry.is_regular_file(ec) || is_hidden(path) || !path.has_extension()) continue;
      if (importer.IsExtensionSupported(path.extension().string())) {
        files.push_back(path.string());
      }
    }
    if (ec) {
      set_error(error, "cannot list " + path_or_dir + ": " + ec.message());
      files.clear();
      return files;
    }
    std::sort(files.begin(), files.end());
    if (files.empty()) set_error(error, "no mesh files in " + path_or_dir);
  } catch (const std::exception& e) {
    set_error(error, "cannot list " + path_or_dir + ": " + e.what());
    files.clear();
  }
  return files;
}

}  // namespace spinhash::host
