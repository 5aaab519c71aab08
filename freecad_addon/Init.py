# The VoroCrust add-on, loaded by FreeCAD with or without its GUI. The App-level functions are in
# VoroCrustMesher (import VoroCrustMesher; VoroCrustMesher.voronoi_mesh(objects, ...)); nothing
# needs registering at start-up.
