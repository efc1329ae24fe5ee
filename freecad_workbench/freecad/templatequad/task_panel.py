"""Task panel of the TemplateQuad mesh object: edit the parameters, see the result.

Top: one summary line (elements, faces, worst and mean quality, the element size
used), the refused faces with a button that selects them in the 3D view, and a
histogram of the scaled Jacobian with a "colour the mesh by quality" switch.
Parameters as FreeCAD's Gmsh mesh object names them (maximum and minimum element
size, element order), then smoothing, corner choice, per-face corners, keep going
and accepting an incomplete mesh; the template details (T4 ratio, template trees,
every refusal's reason) sit in a folded "Advanced" section.

"Mesh" re-meshes (an undoable step) when a value changed; OK does the same and
closes; Cancel restores the values the panel opened with and re-meshes if "Mesh" had
changed them. A mesh cancelled from its progress dialog leaves the previous mesh and
values.
"""
import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui  # FreeCAD's shim: QtGui also holds the widgets

from . import meshing, paths
from .mesh_object import ELEMENT_DIMENSIONS, ELEMENT_ORDERS
from .quality_colours import histogram_band_colour
from .view_provider import show_quality, showing_quality

#: The properties the panel edits, in the order of _values().
_INPUT_NAMES = ("CharacteristicLengthMax", "CharacteristicLengthMin", "ElementOrder",
                "Smooth", "BestCorners", "Corners", "Sew", "KeepGoing", "AcceptIncomplete",
                "T4Ratio", "ElementDimension", "Layers")
_CORNER_CHOICES = ("Automatic", "Best (slower)")


class QualityHistogram(QtGui.QWidget):
    """Bars of the quad count per scaled Jacobian band, coloured as the colour map."""

    def __init__(self):
        super().__init__()
        self.counts = []
        self.setMinimumHeight(70)
        self.setToolTip("Quads per scaled Jacobian band: below 0 (inverted), then tenths "
                        "from 0 to 1 (a square)")

    def set_counts(self, counts):
        self.counts = list(counts)
        self.update()

    def paintEvent(self, event):
        painter = QtGui.QPainter(self)
        width, height = self.width(), self.height()
        label_height = painter.fontMetrics().height()
        if not self.counts or max(self.counts) == 0:
            painter.drawText(0, 0, width, height, QtCore.Qt.AlignCenter, "no mesh")
            return
        bands = len(self.counts)
        bar_width = width / bands
        top = max(self.counts)
        for band, count in enumerate(self.counts):
            r, g, b = histogram_band_colour(band)
            bar_height = 0 if count == 0 else max(1, int((height - label_height - 2) * count / top))
            x = int(band * bar_width)
            painter.fillRect(x + 1, height - label_height - bar_height, max(1, int(bar_width) - 2),
                             bar_height, QtGui.QColor(int(255 * r), int(255 * g), int(255 * b)))
        painter.setPen(self.palette().color(QtGui.QPalette.WindowText))
        # The scale under the bars: 0 where [0, 0.1) starts, 1 at the right end (the
        # first band, below 0, is the inverted quads: the tooltip says so).
        painter.drawText(int(bar_width), height - label_height, width, label_height,
                         QtCore.Qt.AlignLeft, "0")
        painter.drawText(0, height - label_height, width, label_height, QtCore.Qt.AlignRight, "1")


class TemplateQuadTaskPanel:
    """The panel FreeCADGui.Control.showDialog() shows for one mesh object."""

    def __init__(self, obj):
        self.obj = obj
        self.original = self._inputs()
        self.applied = False
        self.form = self._build_form()
        self._load(self.original)
        self._show_results()

    # --- FreeCAD task dialog interface -------------------------------------------------
    def getStandardButtons(self):
        # OK and Cancel only: a third standard button does not fit FreeCAD's default
        # panel width (it clipped the panel); "Mesh" in the form applies.
        buttons = QtGui.QDialogButtonBox
        return int(buttons.Ok | buttons.Cancel)

    def accept(self):
        """OK: apply (only if something changed); close unless the mesh failed."""
        if not self.apply():
            return False
        FreeCADGui.getDocument(self.obj.Document).resetEdit()
        return True

    def reject(self):
        if self.applied and self._inputs() != self.original:
            self._store(self.original)
            self.obj.Proxy.request_mesh(self.obj)
        FreeCADGui.getDocument(self.obj.Document).resetEdit()
        return True

    # --- actions ----------------------------------------------------------------------
    def apply(self) -> bool:
        """Write the panel's values to the object and re-mesh; True if it is meshed.

        Nothing is re-meshed when the values are those already meshed and the mesh
        is not out of date ("Mesh" then OK meshes once). A mesh cancelled by the user restores the values it replaced.
        """
        values = self._edited()
        error = getattr(self.obj.Proxy, "last_error", "")
        stale = "Touched" in self.obj.State or getattr(self.obj, "OutOfDate", False)
        if values == self._inputs() and not error and not stale:
            return True
        doc = self.obj.Document
        before = self._inputs()
        doc.openTransaction("Edit template quad mesh")
        self.obj.Proxy.last_error = ""
        self._store(values)
        refused = self.obj.Proxy.last_error  # a value the object refused as it was set
        if refused:
            doc.abortTransaction()
            self.obj.Proxy.last_error = ""  # the mesh kept is that of the values kept
            self.summary.setText(f"<span style='color:#b00'>Not meshed.</span> {refused}")
            return False
        self.obj.Proxy.request_mesh(self.obj)
        if getattr(self.obj.Proxy, "cancelled", False):
            doc.abortTransaction()
            self._store(before)
            self.obj.purgeTouched()  # the kept mesh is the one of the values restored
            self._load(before)
            self.summary.setText("Cancelled: the previous mesh is kept.")
            return False
        doc.commitTransaction()
        self.applied = True
        self._load(self._inputs())
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
            self.summary.setText("Select one face and its 2 to 4 corner vertices of "
                                 f"{self.obj.Part.Label if self.obj.Part else 'the part'} "
                                 "(Ctrl+click), in order around the face.")
            return
        self.corners.appendPlainText(f"{faces[0]}:{','.join(vertices)}")

    def select_refused_faces(self):
        """Select the refused faces on the part, so the 3D view shows where they are."""
        names = list(self.obj.RefusedFaceNames)
        part = self.obj.Part
        if not names or part is None:
            return
        part.ViewObject.Visibility = True
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(part, names)

    def toggle_quality_colours(self, on):
        if not show_quality(self.obj.ViewObject, on):
            self.quality_colours.setChecked(False)
            self.summary.setText(self.summary.text() + " Recompute the mesh to colour it "
                                 "(this file was saved without the quality of each quad).")

    # --- helpers ----------------------------------------------------------------------
    def _inputs(self):
        """The object's values of _INPUT_NAMES, lengths as plain millimetres."""
        values = (getattr(self.obj, name) for name in _INPUT_NAMES)
        return tuple(getattr(v, "Value", v) for v in values)

    def _values(self):
        corners = [line.strip() for line in self.corners.toPlainText().splitlines()
                   if line.strip()]
        return (self.max_size.value(), self.min_size.value(),
                self.element_order.currentText(), self.smooth.isChecked(),
                self.corner_choice.currentIndex() == 1, corners, self.sew.isChecked(),
                self.keep_going.isChecked(), self.accept_incomplete.isChecked(),
                self.t4_ratio.value(), self.dimension.currentText(), self.layers.value())

    def _edited(self):
        """The values to mesh with: the panel's where the user changed a field since it
        was loaded, the object's own elsewhere, so that a value changed in the property
        editor while the panel is open is kept, not put back by OK."""
        return tuple(panel if panel != loaded else current
                     for panel, loaded, current in zip(self._values(), self.loaded, self._inputs()))

    def _store(self, values):
        """Set the properties whose values differ (an unchanged one stays untouched)."""
        for name, value, current in zip(_INPUT_NAMES, values, self._inputs()):
            if value != current:
                setattr(self.obj, name, value)

    def _load(self, values):
        (max_size, min_size, order, smooth, best, corners, sew, keep_going, accept,
         t4_ratio, dimension, layers) = values
        self.max_size.setValue(max_size)
        self.min_size.setValue(min_size)
        self.element_order.setCurrentIndex(max(0, self.element_order.findText(order)))
        self.smooth.setChecked(smooth)
        self.corner_choice.setCurrentIndex(1 if best else 0)
        self.corners.setPlainText("\n".join(corners))
        self.sew.setChecked(sew)
        self.keep_going.setChecked(keep_going)
        self.accept_incomplete.setChecked(accept)
        self.t4_ratio.setValue(t4_ratio)
        self.dimension.setCurrentIndex(max(0, self.dimension.findText(dimension)))
        self.layers.setValue(layers)
        self.loaded = self._values()  # as the fields show them (rounded as they round)

    def _show_results(self):
        o = self.obj
        error = getattr(o.Proxy, "last_error", "")
        used = o.ElementSizeUsed.Value
        refused = list(o.RefusedFaceNames)
        if error:
            self.summary.setText(f"<span style='color:#b00'>Not meshed.</span> {error}")
        elif o.FemMesh.FaceCount == 0:
            self.summary.setText("Not meshed yet.")
        else:
            faces = " on all faces" if not refused else ""
            self.summary.setText(f"{o.FemMesh.QuadrangleCount} quads{faces}, element size "
                                 f"{used:.3g} mm; scaled Jacobian worst "
                                 f"{o.ScaledJacobianMin:.2f}, mean {o.ScaledJacobianMean:.2f}")
        warning = self._quality_warning() if not error and o.FemMesh.NodeCount else ""
        if warning:
            self.summary.setText(f"{self.summary.text()}<br><span style='color:#b60'>{warning}</span>")
        unsewn = meshing.unsewn_warning(o.UnsewnEdges, o.Sew) if not error else ""
        if unsewn:
            self.summary.setText(f"{self.summary.text()}<br><span style='color:#b60'>"
                                 f"{unsewn}.</span>")
        self.refused_box.setVisible(bool(refused))
        if refused:
            self.refused_label.setText(
                f"<span style='color:#b60'>Incomplete: {', '.join(refused[:6])}"
                f"{' ...' if len(refused) > 6 else ''} not meshed.</span> The solver stops "
                "on this mesh unless 'Solve with holes' is on; Advanced lists why.")
        self.histogram.set_counts(o.QualityHistogram)
        self.quality_colours.setChecked(showing_quality(o.ViewObject))
        details = list(o.RefusedFaces) + list(o.TemplateTrees)
        if o.Quality:
            details.insert(0, o.Quality)
        self.details.setPlainText("\n".join(details))

    def _quality_warning(self) -> str:
        """The warning of a worst element under the WarnBelowQuality preference."""
        from . import worst_elements as worst_module

        o = self.obj
        _, warn_below = worst_module.preferences()
        worst = worst_module.worst_elements(list(o.ElementQuality), 1)
        if not worst:
            return ""
        owner = worst_module.owner_of(worst[0][0], list(o.ElementOwners))
        kind = "Solid" if o.FemMesh.VolumeCount else "Face"
        return worst_module.quality_warning(worst[0][1], f"{kind}{owner + 1}" if owner >= 0 else "", warn_below)

    def show_worst(self):
        from .commands import show_worst_elements
        show_worst_elements(self.obj)

    def _build_form(self):
        form = QtGui.QWidget()
        form.setWindowTitle("Template quad mesh")
        form.setWindowIcon(QtGui.QIcon(paths.icon("TemplateQuad_Mesh")))
        layout = QtGui.QVBoxLayout(form)

        result = QtGui.QGroupBox("Result")
        box = QtGui.QVBoxLayout(result)
        self.summary = QtGui.QLabel()
        self.summary.setWordWrap(True)
        self.summary.setTextInteractionFlags(QtCore.Qt.TextSelectableByMouse)
        box.addWidget(self.summary)
        self.refused_box = QtGui.QWidget()
        refused_layout = QtGui.QVBoxLayout(self.refused_box)
        refused_layout.setContentsMargins(0, 0, 0, 0)
        self.refused_label = QtGui.QLabel()
        self.refused_label.setWordWrap(True)
        refused_layout.addWidget(self.refused_label)
        select = QtGui.QPushButton("Select them")
        select.setToolTip("Select the faces not meshed on the part, in the 3D view")
        select.clicked.connect(self.select_refused_faces)
        refused_layout.addWidget(select)
        box.addWidget(self.refused_box)
        self.histogram = QualityHistogram()
        box.addWidget(self.histogram)
        self.quality_colours = QtGui.QCheckBox("Colour by quality")
        self.quality_colours.setToolTip("Each quad coloured by its scaled Jacobian: green "
                                        "1 (square), yellow 0.6, red 0.2 and below")
        self.quality_colours.toggled.connect(self.toggle_quality_colours)
        box.addWidget(self.quality_colours)
        worst = QtGui.QPushButton("Show worst")
        worst.setToolTip("Highlight the worst elements (lowest scaled Jacobian), zoom onto them "
                         "and list them with their faces in the report view")
        worst.clicked.connect(self.show_worst)
        box.addWidget(worst)
        layout.addWidget(result)

        params = QtGui.QGroupBox("Mesh parameters")
        grid = QtGui.QFormLayout(params)
        grid.setFieldGrowthPolicy(QtGui.QFormLayout.AllNonFixedFieldsGrow)
        grid.setRowWrapPolicy(QtGui.QFormLayout.WrapLongRows)
        self.max_size = self._length_box("Element size: the target edge length; 0 = "
                                         "automatic (bounding-box diagonal / 25)")
        grid.addRow("Max. size:", self.max_size)
        self.min_size = self._length_box("The element size never goes below this "
                                         "(0 = no floor)")
        self.min_size.setSpecialValueText("none")
        grid.addRow("Min. size:", self.min_size)
        self.element_order = QtGui.QComboBox()
        self.element_order.addItems(ELEMENT_ORDERS)
        self.element_order.setToolTip("1st: 4-node quadrilaterals (S4 shells in CalculiX); "
                                      "2nd: 8-node quadrilaterals, edge middles on the part")
        grid.addRow("Order:", self.element_order)
        self.dimension = QtGui.QComboBox()
        self.dimension.addItems(ELEMENT_DIMENSIONS)
        self.dimension.setToolTip("2D: quadrilateral shells on the faces; 3D: hexahedra swept "
                                  "through each solid that is an extrusion or a partial revolution")
        grid.addRow("Dimension:", self.dimension)
        self.layers = QtGui.QSpinBox()
        self.layers.setRange(0, 100000)
        self.layers.setSpecialValueText("from the size")
        self.layers.setToolTip("3D: hexahedra from each solid's source face to its target")
        grid.addRow("Layers:", self.layers)
        self.smooth = QtGui.QCheckBox("Smooth")
        self.smooth.setToolTip("Move interior nodes on the surfaces to better-shaped quads")
        grid.addRow(self.smooth)
        self.corner_choice = QtGui.QComboBox()
        self.corner_choice.addItems(_CORNER_CHOICES)
        self.corner_choice.setToolTip("Best of several: try 2, 3 and 4 curves per face and "
                                      "keep the best elements")
        grid.addRow("Corners:", self.corner_choice)
        self.corners = QtGui.QPlainTextEdit()
        self.corners.setToolTip("Per face, one line: Face4:Vertex1,Vertex5,Vertex8 (the "
                                "vertices where the face's sides begin)")
        self.corners.setMaximumHeight(54)
        grid.addRow("Per face:", self.corners)
        pick = QtGui.QPushButton("Add from selection")
        pick.setToolTip("Select a face and its 2 to 4 corner vertices (Ctrl+click), then "
                        "press to add a line for that face")
        pick.clicked.connect(self.add_corners_from_selection)
        grid.addRow(pick)
        self.sew = QtGui.QCheckBox("Sew faces first")
        self.sew.setToolTip("Join faces that touch without sharing their edge (an IGES "
                            "import of trimmed surfaces), so the mesh is connected there")
        grid.addRow(self.sew)
        self.keep_going = QtGui.QCheckBox("Skip faces that fail")
        self.keep_going.setToolTip("Mesh the other faces when one cannot be meshed "
                                   "(the mesh is then incomplete)")
        grid.addRow(self.keep_going)
        self.accept_incomplete = QtGui.QCheckBox("Solve with holes")
        self.accept_incomplete.setToolTip("Let CalculiX run on this mesh although faces "
                                          "were not meshed")
        grid.addRow(self.accept_incomplete)
        remesh = QtGui.QPushButton("Mesh")
        remesh.setToolTip("Mesh with these parameters now (OK does too, then closes)")
        remesh.clicked.connect(self.apply)
        grid.addRow(remesh)
        layout.addWidget(params)

        advanced_toggle = QtGui.QToolButton()
        advanced_toggle.setText("Advanced")
        advanced_toggle.setCheckable(True)
        advanced_toggle.setToolButtonStyle(QtCore.Qt.ToolButtonTextBesideIcon)
        advanced_toggle.setArrowType(QtCore.Qt.RightArrow)
        layout.addWidget(advanced_toggle)
        self.advanced = QtGui.QWidget()
        advanced = QtGui.QFormLayout(self.advanced)
        self.t4_ratio = QtGui.QSpinBox()
        self.t4_ratio.setRange(2, 1000)
        self.t4_ratio.setToolTip("k of the T4 template test: k*C <= A and k*C <= B")
        advanced.addRow("T4 ratio:", self.t4_ratio)
        self.details = QtGui.QPlainTextEdit()
        self.details.setReadOnly(True)
        self.details.setToolTip("Counts and quality, each refused face's reason, each "
                                "face's template tree")
        advanced.addRow(self.details)
        self.advanced.setVisible(False)

        def fold(shown):
            self.advanced.setVisible(shown)
            advanced_toggle.setArrowType(QtCore.Qt.DownArrow if shown else QtCore.Qt.RightArrow)

        advanced_toggle.toggled.connect(fold)
        layout.addWidget(self.advanced)
        layout.addStretch(1)
        return form

    @staticmethod
    def _length_box(tip: str):
        box = QtGui.QDoubleSpinBox()
        box.setRange(0.0, 1e9)
        box.setDecimals(3)
        box.setSuffix(" mm")
        box.setSpecialValueText("automatic")  # shown for 0
        box.setToolTip(tip)
        return box
