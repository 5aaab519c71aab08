#!/usr/bin/env bash
# The README's first command: installs what is needed, builds, and runs the main job on the
# bundled sample.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
echo
echo "== build/cli/vorocrust info samples/cgal_joint.off"
build/cli/vorocrust info samples/cgal_joint.off
echo
echo "== build/cli/vorocrust mesh samples/cgal_joint.off -o demo-output"
build/cli/vorocrust mesh samples/cgal_joint.off -o demo-output
echo
echo "== build/cli/vorocrust check-balls samples/cgal_joint.off demo-output/balls.csv"
build/cli/vorocrust check-balls samples/cgal_joint.off demo-output/balls.csv
echo
echo
echo "== build/cli/vorocrust quality demo-output"
build/cli/vorocrust quality demo-output
echo
echo "Open demo-output/report.html in a browser: the run's figures, tables and pictures on one page."
echo "The Voronoi mesh is in demo-output/mesh.vtu (open it in ParaView; cell data: material, seed,"
echo "volume, aspect_ratio: a Threshold on it shows the worst cells) and demo-output/case/ (an"
echo "OpenFOAM case: checkMesh -case demo-output/case), and mesh.exo (Exodus II), MESH (TOUGH) and"
echo "pflotran/ (PFLOTRAN)."
echo "The surface is in demo-output/surface.obj and surface.ply (ParaView, MeshLab), its quality"
echo "histogram in demo-output/quality.svg, the seeds in seeds.csv; the protecting balls in balls.csv"
echo "and balls.vtk (in ParaView glyph the points as spheres scaled by 'radius'); report.json holds"
echo "the counts, the sliver rounds, the quality figures and the time of each phase."
