"""TemplateQuad for FreeCAD: all-quadrilateral FEM meshes by hierarchical templates.

Modules (App side first, so everything works in freecadcmd):
    factory       make_mesh(doc, part, ...): the scriptable entry point
    mesh_object   the Fem::FemMeshObjectPython proxy: properties, execute()
    meshing       pure functions: shape -> tquad mesh -> Fem.FemMesh, summaries
    paths         where icons and the tquad module are
GUI only:
    init_gui      the workbench (FreeCAD imports it at GUI start-up)
    commands      TemplateQuad_Mesh
    view_provider icon, double-click -> task panel
    task_panel    edit the parameters, see counts, quality and refused faces

FreeCAD imports this package at start-up, so keep it light: no Fem, no tquad here.
"""
from .factory import make_mesh

__all__ = ["make_mesh"]
