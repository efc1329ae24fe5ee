"""Where the add-on's files are, whether it runs from the repository or installed.

The layout is the same in both places (install.sh copies the folder as it is):

    <root>/package.xml
    <root>/resources/icons/*.svg
    <root>/tquad/                  the compiled module, copied in by install.sh
    <root>/freecad/templatequad/   this package
"""
import os

#: The add-on root: the folder holding package.xml.
ADDON_ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                           os.pardir, os.pardir))

ICON_DIR = os.path.join(ADDON_ROOT, "resources", "icons")


def icon(name: str) -> str:
    """icon(): the absolute path of resources/icons/<name>.svg."""
    return os.path.join(ICON_DIR, name + ".svg")
