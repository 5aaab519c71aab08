"""VoroCrust in FreeCAD without the GUI: Mesh objects and Part solids in, a Voronoi mesh out.

    import VoroCrustMesher
    result = VoroCrustMesher.voronoi_mesh([box, sphere], Parameters(max_size=2, seed=7),
                                          output_dir="/tmp/out")

adds to the document a "VoronoiMesh" group holding one Mesh object per material surface and the
seeds as a Points object, and writes the chosen files (VTU, OpenFOAM case, TOUGH MESH, PFLOTRAN
grid, seeds.csv, surface OBJ/PLY, ...). Everything geometric is done by the `vorocrust` module
(libvorocrust); this file only converts FreeCAD objects to its arrays and its results to
document objects.

Materials: every Part solid and every closed Mesh object is one material, named after its
object (a shape with several solids gives "Label/solid N"), merged as the library merges several
input files: vertices with exactly equal coordinates shared, a face two solids share one
interface between them. Part solids that touch are imprinted on each other first (Part's general
fuse) and tessellated once, so that their common faces have one triangulation.
"""

import os
import shutil
import tempfile

import FreeCAD as App
import numpy as np

import vorocrust

#: What the panel and voronoi_mesh() can write, by format name: the module's formats, so
#: formats the library gains appear here by themselves. report.json is always written.
FORMATS = dict(vorocrust.OUTPUT_FORMATS)
#: Written when nothing else is asked for: the volume mesh, the compact seeds, the surface and
#: report.html (the result window's "Open report").
DEFAULT_FORMATS = ("vtu", "openfoam", "tough", "pflotran", "seeds", "ply", "html")
#: The options of a run: the library's table (vorocrust.OPTIONS), in its order, as the workbench
#: offers them; the panel, the object's properties and Parameters are made from it.
OPTIONS = [o for o in vorocrust.OPTIONS if "freecad" in o["front_ends"]]
#: The FreeCAD property type of each kind of option.
PROPERTY_TYPES = {"flag": "App::PropertyBool", "integer": "App::PropertyInteger", "real": "App::PropertyFloat",
                  "choice": "App::PropertyEnumeration", "choices": "App::PropertyStringList",
                  "file": "App::PropertyFile", "box": "App::PropertyString"}


def option_help(o):
    """An option's help with its default and range, as the table gives them."""
    text = o["help"] + (" (paper %s)" % o["section"] if o["section"] else "")
    text += ". " + o["default_text"][0].upper() + o["default_text"][1:]
    if o["unset_number"] is not None:
        text += " (%g here)" % o["unset_number"]
    if o["kind"] != "flag":
        text += "; range: " + o["range_text"]
    return text + "."


def property_value(o, value):
    """An option's value as its property holds it: unset as the table's unset_number (or an
    empty text), a box as six numbers in a text, formats as a list."""
    if value is None:
        if o["unset_number"] is not None:
            return int(o["unset_number"]) if o["kind"] == "integer" else float(o["unset_number"])
        return [] if o["kind"] == "choices" else ""
    if o["kind"] == "box":
        return " ".join("%r" % float(x) for x in value)
    if o["kind"] == "choices":
        return list(value)
    return value


def option_value(o, value):
    """The inverse of property_value: a widget's or property's value as mesh() takes it."""
    if value is None or (o["unset_number"] is not None and value == o["unset_number"]):
        return None
    if o["kind"] in ("box", "file"):
        text = str(value).strip()
        if not text:
            return None
        return tuple(float(x) for x in text.replace(",", " ").split()) if o["kind"] == "box" else text
    return value


class Parameters:
    """The options of a run, by their names in vorocrust.OPTIONS (as vorocrust.mesh() takes
    them), and the tessellation tolerance of Part shapes: the largest distance (model units)
    between a Part shape and its triangles. An option not given keeps the library's default; a
    number equal to the table's unset_number (a panel's "auto") leaves it unset.

        Parameters(max_size=2, seed=7, smooth=True)
    """

    def __init__(self, tolerance=0.1, **options):
        known = {o["name"]: o for o in OPTIONS}
        unknown = sorted(set(options) - set(known))
        if unknown:
            raise vorocrust.UsageError("unknown option %s: the options are %s" % (
                ", ".join(unknown), ", ".join(known)))
        self.tolerance = tolerance
        self.options = {name: option_value(known[name], value) for name, value in options.items()}

    def __getattr__(self, name):
        if name in ("tolerance", "options"):
            raise AttributeError(name)
        if name in self.options:
            return self.options[name]
        if name in vorocrust.DEFAULT_OPTIONS:
            return vorocrust.DEFAULT_OPTIONS[name]
        raise AttributeError(name)

    def replace(self, **changes):
        """A copy with some options (or the tolerance) changed."""
        tolerance = changes.pop("tolerance", self.tolerance)
        return Parameters(tolerance, **dict(self.options, **changes))

    def mesh_options(self):
        """The keyword arguments of vorocrust.mesh()."""
        return dict(self.options)


def is_meshable(obj):
    """True for the objects a run takes: Mesh objects with facets and Part objects with a shape."""
    if obj.isDerivedFrom("Mesh::Feature"):
        return obj.Mesh.CountFacets > 0
    return obj.isDerivedFrom("Part::Feature") and not obj.Shape.isNull() and len(obj.Shape.Faces) > 0


def _arrays(points, triangles):
    return (np.array([(p.x, p.y, p.z) for p in points], dtype=np.float64).reshape(-1, 3),
            np.array(triangles, dtype=np.int64).reshape(-1, 3))


def _conforming_solids(named_solids, tolerance):
    """The solids imprinted on each other where they touch (Part's general fuse), each as
    (points, triangles) tessellated once for all, so that a face two solids share has one
    triangulation on both sides: the library then meshes it as the interface between their
    materials. Solids that overlap (share volume) raise InvalidGeometryError naming both."""
    for i, (name_a, a) in enumerate(named_solids):
        for name_b, b in named_solids[i + 1:]:
            if a.BoundBox.intersect(b.BoundBox) and a.common(b).Volume > 1e-9 * min(a.Volume, b.Volume):
                raise vorocrust.InvalidGeometryError(
                    "%s and %s intersect: solids may touch but not overlap (their common volume is %g)"
                    % (name_a, name_b, a.common(b).Volume))
    solids = [s for _, s in named_solids]
    if len(solids) == 1:
        fused, pieces = solids[0], [[solids[0]]]
    else:
        fused, pieces = solids[0].generalFuse(solids[1:])
    fused.tessellate(tolerance)  # every face once: faces and edges shared alike
    out = []
    for split in pieces:
        # Faces are tessellated apart; their common edges' points, equal to the last bit, are one.
        points, index, triangles = [], {}, []
        for piece in split:
            for face in piece.Faces:
                p, t = face.tessellate(tolerance)
                ids = []
                for q in p:
                    key = (q.x, q.y, q.z)
                    if key not in index:
                        index[key] = len(points)
                        points.append(q)
                    ids.append(index[key])
                triangles += [(ids[a], ids[b], ids[c]) for a, b, c in t]
        out.append((points, triangles))
    return out


def model_parts(objects, tolerance):
    """The model's parts as (name, vorocrust.Surface): one per Mesh object, one per solid of a
    Part object (its faces, when it has no solid), in global coordinates. Part shapes are
    tessellated so that no triangle lies farther than `tolerance` from the shape; solids that
    touch share their common faces' triangles, which become interfaces between materials."""
    import Part  # only where Part objects are meshed

    if tolerance <= 0:
        raise vorocrust.UsageError("the tessellation tolerance must be positive, got %g" % tolerance)
    parts = []
    solids = []  # (index in parts, name, solid)
    for obj in objects:
        if obj.isDerivedFrom("Mesh::Feature"):
            points, facets = obj.Mesh.Topology  # placement applied
            parts.append((obj.Label, vorocrust.Surface(*_arrays(points, facets), name=obj.Label)))
        elif obj.isDerivedFrom("Part::Feature"):
            shape = Part.getShape(obj)
            if not shape.Solids:
                points, triangles = shape.tessellate(tolerance)
                parts.append((obj.Label, vorocrust.Surface(*_arrays(points, triangles), name=obj.Label)))
            for k, solid in enumerate(shape.Solids):
                name = obj.Label if len(shape.Solids) == 1 else "%s/solid %d" % (obj.Label, k + 1)
                solids.append((len(parts), name, solid))
                parts.append((name, None))
        else:
            raise vorocrust.UsageError("%s is neither a Mesh nor a Part object" % obj.Label)
    if not parts:
        raise vorocrust.UsageError("nothing to mesh: select Mesh objects or Part solids")
    if solids:
        tessellated = _conforming_solids([(name, solid) for _, name, solid in solids], tolerance)
        for (index, name, _), (points, triangles) in zip(solids, tessellated):
            parts[index] = (name, vorocrust.Surface(*_arrays(points, triangles), name=name))
    return parts


def model_of(objects, tolerance):
    """The objects as one vorocrust.Surface (see model_parts)."""
    return vorocrust.merge_surfaces(model_parts(objects, tolerance))


def run(model, parameters, output_dir=None, formats=DEFAULT_FORMATS, progress=None):
    """Meshes a vorocrust.Surface: the library's job (vorocrust.mesh()) with the parameters,
    writing `formats` and report.json into output_dir. Touches no FreeCAD object, so it may run
    in a worker thread while FreeCAD's window goes on."""
    unknown = [f for f in formats if f not in FORMATS]
    if unknown:
        raise vorocrust.UsageError("unknown output format %s: expected some of %s" % (
            ", ".join(map(repr, unknown)), ", ".join(FORMATS)))
    options = parameters.mesh_options()
    options["formats"] = [f for f in formats if f != "report"]
    return vorocrust.mesh(model, output_dir=output_dir, progress=progress, **options)


def write_results(result, folder, formats):
    """Writes the run's files in `formats` into `folder` again; returns their paths."""
    return vorocrust.write_outputs(result, folder, list(formats))


def default_output_dir(doc):
    """Beside the document's file when it has one, else in the temporary folder."""
    if doc.FileName:
        return os.path.join(os.path.dirname(doc.FileName), doc.Name + "_voronoi")
    return os.path.join(tempfile.gettempdir(), "vorocrust-" + doc.Name)


def log_progress():
    """A progress callback writing each new phase to FreeCAD's report."""
    last = [None]

    def progress(phase, fraction):
        stage = phase.split(",")[0]
        if stage != last[0]:
            App.Console.PrintLog("VoroCrust: %s\n" % stage)
            last[0] = stage

    return progress


def voronoi_mesh(objects, parameters=None, output_dir=None, formats=DEFAULT_FORMATS, doc=None, progress=None):
    """Meshes Mesh objects and Part solids, writes the files and adds the result to their
    document.

    parameters: a Parameters (defaults when None).
    output_dir: where the files go (default_output_dir() when None).
    formats: names from FORMATS.
    progress: a callable progress(phase, fraction) as vorocrust.mesh() takes; returning False
        cancels (vorocrust.Cancelled is raised, nothing is written and the document is not
        changed). None logs the phases to FreeCAD's report.

    Returns the new VoronoiMesh group object. Raises vorocrust.Error (with the library's
    message) when the model cannot be meshed.
    """
    parameters = parameters or Parameters()
    objects = list(objects)
    doc = doc or (objects[0].Document if objects else App.ActiveDocument)
    output_dir = output_dir or default_output_dir(doc)
    model = model_of(objects, parameters.tolerance)
    result = run(model, parameters, output_dir, formats, progress or log_progress())
    return add_result(doc, objects, parameters, result, output_dir, formats)


def add_result(doc, objects, parameters, result, output_dir, formats):
    """Adds a finished run's objects to `doc` in one undoable step, and says what it wrote."""
    def build():
        obj = doc.addObject("App::DocumentObjectGroupPython", "VoronoiMesh")
        VoronoiMeshResult(obj)
        obj.Proxy.set_result(obj, objects, parameters, result, output_dir, formats)
        if App.GuiUp:
            import VoroCrustGui

            VoroCrustGui.ViewProviderVoronoiMesh(obj.ViewObject)
        return obj

    obj = _in_one_step(doc, "Voronoi mesh", build, result.summary)
    for path in result.written:
        App.Console.PrintLog("VoroCrust: wrote %s\n" % path)
    return obj


def _in_one_step(doc, title, build, summary):
    """build() in one undoable step of `doc` (none when it raises), then the run's summary in
    FreeCAD's report; returns what build() made."""
    doc.openTransaction(title)
    try:
        made = build()
        doc.recompute()
    except Exception:
        doc.abortTransaction()
        raise
    doc.commitTransaction()
    for line in summary:
        App.Console.PrintMessage("VoroCrust: %s\n" % line)
    return made


def material_surfaces(surface):
    """(region number, region name, vertices, triangles) for every material region of a run's
    output surface: the faces that bound it, turned so their normals point out of it."""
    regions = surface.regions
    names = surface.region_names
    found = []
    for region in sorted(set(np.unique(regions)) - {0, -1}):
        back = regions[:, 0] == region
        front = regions[:, 1] == region
        triangles = np.concatenate([surface.triangles[back], surface.triangles[front][:, ::-1]])
        name = names[region] if region < len(names) else "material %d" % region
        found.append((int(region), name, surface.vertices, triangles))
    return found


def _mesh_of(vertices, triangles):
    import Mesh

    # Mesh.Mesh((points, facets)) wants Vectors: plain tuples crash FreeCAD 0.20.
    points = [App.Vector(*map(float, p)) for p in vertices]
    return Mesh.Mesh((points, [tuple(map(int, t)) for t in triangles]))


def _points_of(positions):
    import Points

    return Points.Points([tuple(map(float, p)) for p in positions])


class VoronoiMeshResult:
    """The document object of a run: its parameters and figures, the output surfaces and seeds
    as children, and the seeds and surface files kept inside the document, so "Export Voronoi
    mesh" can write the volume mesh again after the document was saved and reopened."""

    def __init__(self, obj):
        obj.Proxy = self
        self._result = None
        add = obj.addProperty
        add("App::PropertyLinkList", "Sources", "Input", "The Mesh objects and Part solids meshed")
        add("App::PropertyFloat", "Tolerance", "Input", "Tessellation tolerance of Part shapes")
        for o in OPTIONS:
            if o["name"] == "formats":
                continue  # the Formats property below says what was written
            add(PROPERTY_TYPES[o["kind"]], o["freecad"], "Options: " + o["group"], option_help(o))
            if o["kind"] == "choice":
                setattr(obj, o["freecad"], list(o["choices"]))
            setattr(obj, o["freecad"], property_value(o, o["default"]))
        add("App::PropertyPath", "OutputFolder", "Output", "Where the files were written")
        add("App::PropertyStringList", "Formats", "Output", "The formats written")
        add("App::PropertyFileIncluded", "SeedsFile", "Output", "The seeds (seeds.csv), kept in the document")
        add("App::PropertyFileIncluded", "SurfaceFile", "Output", "The output surface (surface.ply), kept in the document")
        add("App::PropertyInteger", "SeedCount", "Figures", "Seeds")
        add("App::PropertyInteger", "SurfaceTriangles", "Figures", "Triangles of the output surface")
        add("App::PropertyInteger", "CellCount", "Figures", "Cells of the volume mesh")
        add("App::PropertyFloat", "Volume", "Figures", "Sum of the cell volumes")
        add("App::PropertyFloat", "QualityMin", "Figures", "Smallest triangle quality Q of the output surface")
        add("App::PropertyFloat", "HausdorffPercent", "Figures", "Hausdorff distance to the input, % of its diagonal")
        add("App::PropertyBool", "TopologyMatches", "Figures", "The output surface has the input's topology")
        for name in ("SeedCount", "SurfaceTriangles", "CellCount", "Volume", "QualityMin", "HausdorffPercent",
                     "TopologyMatches"):
            obj.setEditorMode(name, 1)  # read-only

    def set_result(self, obj, objects, parameters, result, output_dir, formats):
        """Fills the object from a finished run (the options in force, its figures) and adds its
        surfaces and seeds as children."""
        self._result = result
        doc = obj.Document
        obj.Sources = list(objects)
        obj.Tolerance = parameters.tolerance
        in_force = result.options  # an unset default resolved: the sharp angle of the mode
        for o in OPTIONS:
            if o["name"] != "formats":
                setattr(obj, o["freecad"], property_value(o, in_force[o["name"]]))
        obj.OutputFolder = output_dir
        obj.Formats = list(formats)
        staging = tempfile.mkdtemp(prefix="vorocrust-freecad-")
        try:
            vorocrust.write_seeds(result.seeds, os.path.join(staging, "seeds.csv"))
            vorocrust.write_surface(result.surface, os.path.join(staging, "surface.ply"))
            obj.SeedsFile = os.path.join(staging, "seeds.csv")  # FreeCAD copies it into the document
            obj.SurfaceFile = os.path.join(staging, "surface.ply")
        finally:
            shutil.rmtree(staging, ignore_errors=True)
        quality = result.surface_quality
        obj.SeedCount = len(result.seeds)
        obj.SurfaceTriangles = result.surface.num_faces
        obj.QualityMin = quality["triangle_quality"]["min"]
        obj.HausdorffPercent = quality["hausdorff"]["percent_of_bounding_box_diagonal"]
        obj.TopologyMatches = quality["topology"]["matches"]
        if result.cells is not None:
            obj.CellCount = result.cells.num_cells
            obj.Volume = float(result.cells.volumes.sum())

        for region, name, vertices, triangles in material_surfaces(result.surface):
            surface = doc.addObject("Mesh::Feature", "VoronoiSurface")
            surface.Label = "Voronoi surface: %s" % name
            surface.Mesh = _mesh_of(vertices, triangles)
            obj.addObject(surface)
        seeds = doc.addObject("Points::Feature", "VoronoiSeeds")
        seeds.Label = "Voronoi seeds"
        seeds.Points = _points_of(result.seeds.positions)
        obj.addObject(seeds)

    def result(self):
        """The run's vorocrust.MeshResult while FreeCAD has it in memory (not after reopening)."""
        return self._result

    def execute(self, obj):
        pass

    # FreeCAD 0.20 saves proxies with __getstate__, later versions with dumps: the run itself
    # stays out of the document (its seeds and surface are there as files).
    def __getstate__(self):
        return None

    def __setstate__(self, state):
        self._result = None

    def dumps(self):
        return None

    def loads(self, state):
        self._result = None


def is_result(obj):
    """True for the VoronoiMesh objects voronoi_mesh() adds."""
    return obj is not None and isinstance(getattr(obj, "Proxy", None), VoronoiMeshResult)


def export_result(obj, folder, formats):
    """Writes a VoronoiMesh object's files again into `folder`: from the run when FreeCAD still
    holds it, else from the seeds and surface kept in the document (the volume formats then
    from the cells of those seeds, which are the run's cells: the seeds are the whole mesh in
    compact form). Returns the paths written."""
    result = obj.Proxy.result()
    if result is not None:
        return write_results(result, folder, formats)
    seeds = vorocrust.read_seeds(obj.SeedsFile)
    surface = vorocrust.read_mesh(obj.SurfaceFile)
    unavailable = [f for f in formats if f in ("balls", "svg", "html", "report")]
    if unavailable:
        raise vorocrust.UsageError("%s: only the run itself has these; the document keeps its seeds and surface "
                                   "(run Voronoi mesh again for them)" % ", ".join(unavailable))
    return vorocrust.write_files(folder, list(formats), seeds=seeds, surface=surface,
                                 cells=vorocrust.compute_cells(seeds) if any(f in vorocrust.VOLUME_FORMATS for f in formats) else None)


# 2D domains (paper 2.6): sketches and Draft wires.

#: What a 2D run can write (vorocrust.PLANE_FORMATS), and what it writes unless told otherwise.
PLANE_FORMATS = tuple(vorocrust.PLANE_FORMATS)
DEFAULT_PLANE_FORMATS = ("vtu", "svg", "openfoam", "tough", "pflotran", "seeds")
#: The options a 2D run takes, of OPTIONS.
PLANE_OPTIONS = [o for o in OPTIONS if o["name"] in vorocrust.PLANE_OPTIONS]


def is_planar_wire(obj):
    """True for Part objects whose shape is edges without faces: sketches, Draft wires, lines."""
    if not obj.isDerivedFrom("Part::Feature") or obj.Shape.isNull():
        return False
    return len(obj.Shape.Edges) > 0 and len(obj.Shape.Faces) == 0


def _inside(point, polygon):
    """Whether a point lies inside a closed polygon (a list of (x, y)), by crossings."""
    x, y = point
    inside = False
    for (x1, y1), (x2, y2) in zip(polygon, polygon[1:] + polygon[:1]):
        if (y1 > y) != (y2 > y) and x < x1 + (y - y1) * (x2 - x1) / (y2 - y1):
            inside = not inside
    return inside


def planar_domain(objects, tolerance):
    """The wires of `objects` as a 2D domain for vorocrust.mesh2d(), in the plane of the first
    object (its Placement): returns (domain, placement). Curves become polylines within
    `tolerance` of them; points that meet are shared. As Part makes faces of a sketch, a closed
    wire inside an odd number of others bounds a hole; open wires inside a region are
    breaklines. Raises ValueError when the wires do not lie in one plane."""
    placement = objects[0].Placement
    to_plane = placement.inverse()
    points, index, segments, closed = [], {}, [], []
    size = max(max(o.Shape.BoundBox.XLength, o.Shape.BoundBox.YLength, o.Shape.BoundBox.ZLength) for o in objects)
    snap = 1e-9 * max(size, 1e-300)

    def point_id(v):
        local = to_plane.multVec(v)
        if abs(local.z) > max(tolerance, 1e-7 * size):
            raise ValueError("the wires do not lie in one plane: a point lies %g from the plane of %s" % (
                local.z, objects[0].Label))
        key = (round(local.x / snap), round(local.y / snap))
        if key not in index:
            index[key] = len(points)
            points.append((local.x, local.y))
        return index[key]

    for obj in objects:
        for wire in obj.Shape.Wires:
            chain = []
            for edge in wire.OrderedEdges:
                if edge.Curve.TypeId == "Part::GeomLine":
                    along = [edge.Vertexes[0].Point, edge.Vertexes[-1].Point]
                    if edge.Orientation == "Reversed":
                        along.reverse()
                else:
                    along = edge.discretize(Deflection=tolerance)
                    if edge.Orientation == "Reversed":
                        along.reverse()
                ids = [point_id(v) for v in along]
                for a, b in zip(ids, ids[1:]):
                    if a != b:
                        segments.append((a, b))
                chain += ids if not chain else ids[1:]
            if wire.isClosed() and len(chain) > 3:
                closed.append([points[i] for i in chain[:-1]])
        # Edges in no wire (loose sketch geometry).
        in_wires = {e.hashCode() for w in obj.Shape.Wires for e in w.Edges}
        for edge in obj.Shape.Edges:
            if edge.hashCode() in in_wires:
                continue
            ids = [point_id(v) for v in edge.discretize(Deflection=tolerance)]
            segments += [(a, b) for a, b in zip(ids, ids[1:]) if a != b]
    holes = []
    for k, polygon in enumerate(closed):
        depth = sum(1 for j, other in enumerate(closed) if j != k and _inside(polygon[0], other))
        if depth % 2 == 1:
            # Just inside the wire, beside the middle of its first side.
            (x1, y1), (x2, y2) = polygon[0], polygon[1]
            mx, my, nx, ny = (x1 + x2) / 2, (y1 + y2) / 2, y1 - y2, x2 - x1
            for side in (1e-3, -1e-3):
                candidate = (mx + side * nx, my + side * ny)
                if _inside(candidate, polygon):
                    holes.append(candidate)
                    break
    unique = sorted({(min(a, b), max(a, b)) for a, b in segments})
    return {"points": np.array(points, dtype=np.float64).reshape(-1, 2),
            "segments": np.array(unique, dtype=np.int64).reshape(-1, 2),
            "holes": holes}, placement


def run_2d(domain, parameters, output_dir=None, formats=DEFAULT_PLANE_FORMATS, thickness=1.0):
    """Meshes a domain of planar_domain() with vorocrust.mesh2d() and the parameters' options
    that a 2D run takes; returns the PlaneMesh. Touches no FreeCAD object, so it may run in a
    worker thread."""
    given = parameters.mesh_options()
    options = {o["name"]: given[o["name"]] for o in PLANE_OPTIONS if given.get(o["name"]) is not None}
    return vorocrust.mesh2d(domain, output_dir=output_dir, formats=list(formats), thickness=thickness, **options)


def add_result_2d(doc, result, placement, label="VoronoiMesh2D"):
    """The cells of a 2D run in `doc`, in one undoable step: a group holding one Mesh object per
    region (each cell a fan of triangles, in the plane of the input) and the seeds of the cells
    as a Points object."""
    import Points

    def build():
        group = doc.addObject("App::DocumentObjectGroup", label)
        vertices = [placement.multVec(App.Vector(float(x), float(y), 0)) for x, y in result.points]
        for region in sorted(set(result.regions.tolist())):
            triangles = [(cell[0], cell[k], cell[k + 1])
                         for cell, r in zip(result.cells, result.regions) if r == region
                         for k in range(1, len(cell) - 1)]
            name = result.region_names[region] if region < len(result.region_names) else "region%d" % region
            mesh = doc.addObject("Mesh::Feature", "Cells")
            mesh.Label = "%s cells" % name
            mesh.Mesh = _mesh_of([(v.x, v.y, v.z) for v in vertices], triangles)
            group.addObject(mesh)
        seeds = doc.addObject("Points::Feature", "Seeds")
        seeds.Points = Points.Points([tuple(placement.multVec(App.Vector(float(x), float(y), 0)))
                                      for x, y in result.seeds[result.cell_seeds]])
        group.addObject(seeds)
        return group

    return _in_one_step(doc, "Voronoi mesh 2D", build, result.summary)


def voronoi_mesh_2d(objects, parameters=None, output_dir=None, formats=DEFAULT_PLANE_FORMATS, thickness=1.0, doc=None):
    """Meshes sketches or Draft wires as a 2D domain, writes the files and adds the cells to the
    document; returns (the group, the PlaneMesh). Raises vorocrust.Error with the library's
    message (an open boundary, a region point in no region) or ValueError (wires in no plane)."""
    parameters = parameters or Parameters()
    objects = list(objects)
    doc = doc or objects[0].Document
    output_dir = output_dir or default_output_dir(doc)
    domain, placement = planar_domain(objects, parameters.tolerance)
    result = run_2d(domain, parameters, output_dir, formats, thickness)
    return add_result_2d(doc, result, placement), result
