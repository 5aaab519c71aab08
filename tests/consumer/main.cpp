// Reads a mesh through the installed library and prints what a caller would check.
#include <cstdio>
#include <vorocrust/vorocrust.hpp>
#ifdef WITH_OPENMESH
#include <vorocrust/openmesh.hpp>
#endif

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  try {
    vorocrust::SurfaceMesh mesh = vorocrust::read_mesh(argv[1]);
    const vorocrust::MeshInfo info = vorocrust::mesh_info(mesh);
    std::printf("vorocrust %s faces %zu genus %d\n", VOROCRUST_VERSION, info.faces, info.genus.value_or(-1));
#ifdef WITH_OPENMESH
    const auto om = vorocrust::to_openmesh(mesh);
    std::printf("openmesh faces %zu\n", static_cast<std::size_t>(om.n_faces()));
#endif
  } catch (const vorocrust::Error& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
