// The table of a mesh run's outputs.
#include <array>

#include "vorocrust/outputs.hpp"

namespace vorocrust {

namespace {

constexpr std::array<std::string_view, 1> kVtu = {"mesh.vtu"};
constexpr std::array<std::string_view, 1> kCase = {"case"};
constexpr std::array<std::string_view, 1> kMesh = {"MESH"};
constexpr std::array<std::string_view, 1> kPflotran = {"pflotran"};
constexpr std::array<std::string_view, 1> kExodus = {"mesh.exo"};
constexpr std::array<std::string_view, 1> kTets = {"tets.vtu"};
constexpr std::array<std::string_view, 1> kSeeds = {"seeds.csv"};
constexpr std::array<std::string_view, 1> kObj = {"surface.obj"};
constexpr std::array<std::string_view, 1> kPly = {"surface.ply"};
constexpr std::array<std::string_view, 3> kBalls = {"balls.csv", "balls.vtk", "smoothed_surface.ply"};
constexpr std::array<std::string_view, 1> kSvg = {"quality.svg"};
constexpr std::array<std::string_view, 1> kHtml = {"report.html"};

// In the order of OutputFormat, and of ChoiceNames<OutputFormat>.
const std::array<OutputFormatSpec, 12> kOutputs = {{
    {OutputFormat::Vtu, "vtu", kVtu, Stage::Cells, true,
     "one VTK polyhedron per cell with its material, seed, volume and aspect ratio (ParaView)"},
    {OutputFormat::OpenFoam, "openfoam", kCase, Stage::Cells, true,
     "an OpenFOAM case: a patch per boundary region pair, a cell zone per material, a face zone per interface"},
    {OutputFormat::Tough, "tough", kMesh, Stage::Cells, true, "TOUGH's ELEME and CONNE blocks (TOUGH2, TOUGH3)"},
    {OutputFormat::Pflotran, "pflotran", kPflotran, Stage::Cells, true,
     "PFLOTRAN's explicit unstructured grid, a cell list per material, boundary connections per patch"},
    {OutputFormat::Exodus, "exodus", kExodus, Stage::Cells, true,
     "Exodus II: a polyhedral block per material, side sets per boundary patch and interface, the seeds as cell "
     "variables (ParaView, SEACAS codes)"},
    {OutputFormat::Tets, "tets", kTets, Stage::Cells, false,
     "the tetrahedra dual to a clipped mesh (Yan et al.): a point per seed, a tetrahedron per Voronoi vertex "
     "inside a material, with its material and shape measures Q1 to Q4 (clipped meshes only)"},
    {OutputFormat::Seeds, "seeds", kSeeds, Stage::Surface, false,
     "the seeds with label, radius and kind: the whole mesh in compact form"},
    {OutputFormat::SurfaceObj, "obj", kObj, Stage::Surface, false,
     "the conforming surface, its faces grouped by the regions they separate"},
    {OutputFormat::SurfacePly, "ply", kPly, Stage::Surface, false,
     "the conforming surface, each face with the regions it separates"},
    {OutputFormat::Balls, "balls", kBalls, Stage::Balls, false,
     "the protecting balls, and the smoothed input they cover when smoothing changed it (none for a clipped mesh)"},
    {OutputFormat::QualitySvg, "svg", kSvg, Stage::Surface, false, "the histograms of triangle and cell quality"},
    {OutputFormat::ReportHtml, "html", kHtml, Stage::Surface, false,
     "a page to open in a browser: the run's figures and quality tables, pictures of the surface, of a cut "
     "through the cells and of the worst cells, and the histograms"},
}};

}  // namespace

std::span<const OutputFormatSpec> output_formats() noexcept { return kOutputs; }

const OutputFormatSpec& output_format(OutputFormat format) noexcept {
  return kOutputs[static_cast<std::size_t>(format)];
}

}  // namespace vorocrust
