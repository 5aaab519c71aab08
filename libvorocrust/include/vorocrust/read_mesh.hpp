// vorocrust/read_mesh.hpp — reading triangle meshes from OFF, OBJ, STL and PLY.
//
// The format is chosen by extension and confirmed by content (an STL that says `solid` but is
// binary is read as binary). Readers keep every face as written: non-manifold edges, open
// boundaries and several components survive. Only STL, which stores each triangle's corners
// separately, has its exactly equal vertices merged; no coordinate is ever moved.
// Polygons with more than three corners are split into a triangle fan.
//
// Contract: returns a mesh with at least one triangle, every index in range, every coordinate
// finite; otherwise throws vorocrust::Error naming the file and line (or byte offset).
#pragma once

#include "vorocrust/api.hpp"

#include <filesystem>
#include <string>
#include <vector>

#include "vorocrust/surface_mesh.hpp"

namespace vorocrust {

enum class MeshFormat { Off, Obj, Stl, Ply };

// Throws Error(UnreadableInput) when the extension is none of .off .obj .stl .ply.
VOROCRUST_API MeshFormat format_from_extension(const std::filesystem::path& path);

VOROCRUST_API SurfaceMesh read_mesh(const std::filesystem::path& path);

// Several files merge into one model. Each file becomes its own group (its `o`/`g` groups or
// STL solids, when it has several, keep their names prefixed by the file's stem). A vertex with
// exactly the coordinates of one read from an earlier file is shared, so solids that touch
// along common faces stay connected.
VOROCRUST_API SurfaceMesh read_meshes(const std::vector<std::filesystem::path>& paths);

}  // namespace vorocrust
