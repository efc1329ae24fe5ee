"""Where the add-on's files are, whether it runs from the repository or installed.

The layout is the same in both places (install.sh and the Debian package copy it):

    <root>/package.xml, LICENSE       the add-on's metadata (FreeCAD reads package.xml)
    <root>/freecad_workbench/         the workbench folder FreeCAD puts on sys.path
        resources/icons/*.svg
        tquad/                        the compiled module (copied in when installed)
        freecad/templatequad/         this package
"""
import os

#: The workbench folder: the one holding freecad/ (and, installed, tquad/).
WORKBENCH_DIR = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                              os.pardir, os.pardir))

ICON_DIR = os.path.join(WORKBENCH_DIR, "resources", "icons")


def icon(name: str) -> str:
    """icon(): the absolute path of resources/icons/<name>.svg."""
    return os.path.join(ICON_DIR, name + ".svg")
