// vorocrust/exodus.hpp — a VoronoiMesh as an Exodus II file, and back.
//
// write_exodus(mesh, path) writes one Exodus II file (netCDF, 64-bit offsets) that ParaView and
// the codes built on SEACAS read:
// - the mesh's points as the nodes, in order;
// - every face once, in one NSIDED face block (id 1, named "faces"), in the mesh's face order,
//   its nodes in the order whose normal points out of its owner cell;
// - one NFACED element block per material, its id the material's label and its name the
//   material's name made a word (as the OpenFOAM case names its cell zones); its elements the
//   material's cells in cell order, each the list of its faces. The element id map gives each
//   element its cell's index + 1 (mesh.vtu's order);
// - a side set per boundary patch, `<material>_to_<region across>`, and per interface between two
//   materials, `<lower label's>_to_<higher label's>` seen from the lower label's cells, as the
//   OpenFOAM case names its patches and face zones; each side is (element, its face's position in
//   the element's list, from 1), and the integer properties FROM_REGION and TO_REGION hold the
//   two labels;
// - element variables at time 0: seed (its index in the seed set, as in mesh.vtu), sitex, sitey,
//   sitez (the seed's position, where simulators put the cell's values; ParaView shows the vector
//   "site") and volume.
// ParaView reads it with its Exodus II reader (`ExodusIIReader`); 5.11's default IOSS reader does
// not take NSIDED face blocks. The file is written atomically; throws Error(Output) when it cannot be, or when a material's
// label is not positive (an Exodus block id must be).
//
// read_exodus(path) reads such a file back into a VoronoiMesh: points, faces with their owner and
// neighbour cells (owner the first element listing a face, neighbour the second) and the regions
// on each side, cells with their region (the block id), seed, site, volume and centroid (measured
// from the faces), and region_names from the block and side set names. A boundary face's
// neighbour_seed is not stored; it reads as its owner's seed. Throws Error(UnreadableInput),
// naming the file, for a file that is not an Exodus II file of NFACED blocks over one NSIDED
// face block.
#pragma once

#include "vorocrust/api.hpp"

#include <filesystem>

#include "vorocrust/cells.hpp"

namespace vorocrust {

VOROCRUST_API void write_exodus(const VoronoiMesh& mesh, const std::filesystem::path& path);
VOROCRUST_API VoronoiMesh read_exodus(const std::filesystem::path& path);

}  // namespace vorocrust
