"""Task panel of the TemplateQuad mesh object: edit the parameters, see the result.

Inputs: Size (0 = automatic), T4 ratio, keep going, corner overrides (one
``FACE:V1,V2,...`` entry per line; "Add from selection" writes one from a face and its
vertices picked in the 3D view). Outputs: element count and quality, each face's
template tree, refused faces, and the error when meshing failed.

Apply re-meshes (an undoable step); OK applies and closes; Cancel restores the values
the panel opened with and re-meshes if Apply had changed them.
"""
import FreeCADGui
from PySide import QtCore, QtGui  # FreeCAD's shim: QtGui also holds the widgets

from . import paths

_INPUT_NAMES = ("Size", "T4Ratio", "KeepGoing", "Corners")


class TemplateQuadTaskPanel:
    """The panel FreeCADGui.Control.showDialog() shows for one mesh object."""

    def __init__(self, obj):
        self.obj = obj
        self.original = self._inputs()
        self.applied = False
        self.form = self._build_form()
        self._load()
        self._show_results()

    # --- FreeCAD task dialog interface -------------------------------------------------
    def getStandardButtons(self):
        buttons = QtGui.QDialogButtonBox
        return int(buttons.Ok | buttons.Apply | buttons.Cancel)

    def clicked(self, button):
        if button == int(QtGui.QDialogButtonBox.Apply):
            self.apply()

    def accept(self):
        """OK: apply; close unless the mesh failed (then the panel shows why)."""
        if not self.apply():
            return False
        FreeCADGui.getDocument(self.obj.Document).resetEdit()
        return True

    def reject(self):
        if self.applied and self._inputs() != self.original:
            self._store(self.original)
            self.obj.Document.recompute()
        FreeCADGui.getDocument(self.obj.Document).resetEdit()
        return True

    # --- actions ----------------------------------------------------------------------
    def apply(self) -> bool:
        """Write the panel's values to the object and re-mesh; True if it meshed."""
        doc = self.obj.Document
        doc.openTransaction("Edit template quad mesh")
        self._store(self._values())
        doc.recompute()
        doc.commitTransaction()
        self.applied = True
        self._show_results()
        return not self.obj.Proxy.last_error

    def add_corners_from_selection(self):
        """Append "FaceN:VertexA,VertexB,..." from the face and vertices selected."""
        faces, vertices = [], []
        for sel in FreeCADGui.Selection.getSelectionEx():
            if sel.Object != self.obj.Part:
                continue
            for name in sel.SubElementNames:
                if name.startswith("Face"):
                    faces.append(name)
                elif name.startswith("Vertex"):
                    vertices.append(name)
        if len(faces) != 1 or not 2 <= len(vertices) <= 4:
            self.status.setText("Select one face and its 2 to 4 corner vertices of "
                                f"{self.obj.Part.Label if self.obj.Part else 'the part'} "
                                "(Ctrl+click), in order around the face.")
            return
        self.corners.appendPlainText(f"{faces[0]}:{','.join(vertices)}")

    # --- helpers ----------------------------------------------------------------------
    def _inputs(self):
        o = self.obj
        return (o.Size.Value, o.T4Ratio, o.KeepGoing, list(o.Corners))

    def _values(self):
        corners = [line.strip() for line in self.corners.toPlainText().splitlines()
                   if line.strip()]
        return (self.size.value(), self.t4_ratio.value(), self.keep_going.isChecked(),
                corners)

    def _store(self, values):
        size, t4_ratio, keep_going, corners = values
        o = self.obj
        o.Size, o.T4Ratio, o.KeepGoing, o.Corners = size, t4_ratio, keep_going, corners

    def _load(self):
        size, t4_ratio, keep_going, corners = self._inputs()
        self.size.setValue(size)
        self.t4_ratio.setValue(t4_ratio)
        self.keep_going.setChecked(keep_going)
        self.corners.setPlainText("\n".join(corners))

    def _show_results(self):
        o = self.obj
        error = getattr(o.Proxy, "last_error", "")
        if error:
            self.status.setText(f"<span style='color:#b00'>Not meshed: {error}</span>")
        else:
            self.status.setText(o.Quality or "Not meshed yet.")
        self.trees.setPlainText("\n".join(o.TemplateTrees))
        self.refused.setPlainText("\n".join(o.RefusedFaces) or "none")

    def _build_form(self):
        form = QtGui.QWidget()
        form.setWindowTitle("Template quad mesh")
        form.setWindowIcon(QtGui.QIcon(paths.icon("TemplateQuad_Mesh")))
        layout = QtGui.QVBoxLayout(form)

        params = QtGui.QGroupBox("Parameters")
        grid = QtGui.QFormLayout(params)
        self.size = QtGui.QDoubleSpinBox()
        self.size.setRange(0.0, 1e9)
        self.size.setDecimals(3)
        self.size.setSuffix(" mm")
        self.size.setSpecialValueText("automatic")  # shown for 0
        self.size.setToolTip("Target edge length; 0 = bounding-box diagonal / 25")
        grid.addRow("Element size:", self.size)
        self.t4_ratio = QtGui.QSpinBox()
        self.t4_ratio.setRange(2, 1000)
        self.t4_ratio.setToolTip("k of the T4 template test: k*C <= A and k*C <= B")
        grid.addRow("T4 ratio:", self.t4_ratio)
        self.keep_going = QtGui.QCheckBox("Mesh the other faces when one is refused")
        grid.addRow(self.keep_going)
        self.corners = QtGui.QPlainTextEdit()
        self.corners.setToolTip("One face per line: Face4:Vertex1,Vertex5,Vertex8 "
                                "(FreeCAD names) or 3:0,4,7 (0-based indices)")
        self.corners.setMaximumHeight(80)
        grid.addRow("Corners:", self.corners)
        pick = QtGui.QPushButton("Add from selection")
        pick.clicked.connect(self.add_corners_from_selection)
        grid.addRow(pick)
        layout.addWidget(params)

        results = QtGui.QGroupBox("Result")
        box = QtGui.QVBoxLayout(results)
        self.status = QtGui.QLabel()
        self.status.setWordWrap(True)
        self.status.setTextInteractionFlags(QtCore.Qt.TextSelectableByMouse)
        box.addWidget(self.status)
        box.addWidget(QtGui.QLabel("Template trees:"))
        self.trees = QtGui.QPlainTextEdit()
        self.trees.setReadOnly(True)
        box.addWidget(self.trees)
        box.addWidget(QtGui.QLabel("Refused faces:"))
        self.refused = QtGui.QPlainTextEdit()
        self.refused.setReadOnly(True)
        self.refused.setMaximumHeight(60)
        box.addWidget(self.refused)
        layout.addWidget(results)
        return form
