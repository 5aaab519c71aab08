# The VoroCrust workbench: "Voronoi mesh" and "Export Voronoi mesh" in a menu and a toolbar.
# FreeCAD runs this file at start-up with the names Workbench, Gui and FreeCAD defined.


class VoroCrustWorkbench(Workbench):  # noqa: F821 (FreeCAD defines Workbench)
    """Conforming Voronoi meshes of Mesh objects and Part solids, by libvorocrust."""

    MenuText = "VoroCrust"
    ToolTip = "Conforming Voronoi meshes of Mesh objects and Part solids (VoroCrust)"

    def __init__(self):
        import VoroCrustResources

        self.__class__.Icon = VoroCrustResources.icon("VoroCrustWorkbench.svg")

    def Initialize(self):
        try:
            import VoroCrustGui
        except ImportError as e:
            FreeCAD.Console.PrintError(  # noqa: F821
                "VoroCrust: the vorocrust Python module cannot be loaded (%s); install the add-on with "
                "scripts/install-freecad-addon.sh, which puts the module beside it\n" % e)
            return
        self.appendToolbar("VoroCrust", VoroCrustGui.COMMANDS)
        self.appendMenu("&VoroCrust", VoroCrustGui.COMMANDS)

    def GetClassName(self):
        return "Gui::PythonWorkbench"


Gui.addWorkbench(VoroCrustWorkbench())  # noqa: F821
