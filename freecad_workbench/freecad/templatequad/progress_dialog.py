"""Meshing beside a progress dialog with a Cancel button (GUI only).

The mesher runs in a worker thread; the main thread keeps FreeCAD's window alive
(repaints, the dialog's Cancel) until it is done. The two meet only in the mesher's
progress callback: it records the stage and answers whether Cancel was pressed, and
tquad then stops before its next step and raises tquad.Cancelled. Qt is touched from
the main thread only.

The mesher releases the GIL while it works and takes it for each progress call; the
main thread waits with ``Thread.join(timeout)``, which releases it too, so neither
blocks the other.
"""
import threading

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

from . import meshing

#: Where the user's TemplateQuad preferences live, and the one that sets above how
#: many estimated quads a run asks first (0: never ask).
PREFERENCES = "User parameter:BaseApp/Preferences/Mod/TemplateQuad"
ASK_ABOVE_QUADS = "AskAboveQuads"
ASK_ABOVE_DEFAULT = 1_000_000


def _amount(n: int, giga: str, unit: str) -> str:
    """"2,400 quads", "8.2 million quads"; bytes as "350 MB", "5.7 GB"."""
    if unit == "bytes":
        return f"{n / 1e9:.1f}{giga}" if n >= 1e9 else f"{n / 1e6:.0f} MB"
    return f"{n / 1e6:.1f} million {unit}" if n >= 1e6 else f"{n:,} {unit}"


def confirm_large_run(label: str, quads: int, memory: int) -> bool:
    """Whether to mesh: True at once for an estimate up to the preference; above it the
    user is shown the estimated quads and memory and asked (No is the default)."""
    limit = FreeCAD.ParamGet(PREFERENCES).GetInt(ASK_ABOVE_QUADS, ASK_ABOVE_DEFAULT)
    if limit <= 0 or quads <= limit:
        return True
    buttons = QtGui.QMessageBox.Yes | QtGui.QMessageBox.No
    answer = QtGui.QMessageBox.question(
        FreeCADGui.getMainWindow(), "TemplateQuad",
        f"{label}: about {_amount(quads, '', 'quads')} and {_amount(memory, ' GB', 'bytes')} of memory "
        f"at this element size (more than {limit:,} quads); FreeCAD then takes about "
        f"{quads * HANDOVER_SECONDS_PER_QUAD:.0f} s to take the mesh in, while its window does not "
        f"answer. Mesh anyway?", buttons, QtGui.QMessageBox.No)
    return answer == QtGui.QMessageBox.Yes


#: A mesh taking less than this many milliseconds shows no dialog at all.
SHOW_AFTER_MS = 400
#: How often the main thread looks at the worker's progress (seconds).
POLL_SECONDS = 0.05
#: Steps of the dialog's bar for one stage of the mesher.
BAR_STEPS = 1000


class _Progress:
    """What the worker reports and what the dialog asks, shared under a lock."""

    def __init__(self):
        self.lock = threading.Lock()
        self.stage, self.done, self.total = "starting", 0, 1
        self.cancel = threading.Event()

    def __call__(self, stage: str, done: int, total: int) -> bool:
        """The mesher's progress callback (worker thread): True asks it to stop."""
        with self.lock:
            self.stage, self.done, self.total = stage, done, max(total, 1)
        return self.cancel.is_set()

    def snapshot(self):
        with self.lock:
            return self.stage, self.done, self.total


def run_with_progress(work, title: str):
    """run_with_progress(): work(progress) in a worker thread, a dialog meanwhile.

    Returns work's result, or None when the user pressed Cancel while the dialog was
    up (the mesher stopped, or its result is dropped when it finished first; nothing
    was changed). Any other exception of work is raised here.
    """
    progress = _Progress()
    outcome = {}

    def target():
        try:
            outcome["result"] = work(progress)
        except BaseException as error:  # handed to the main thread, raised there
            outcome["error"] = error

    dialog = QtGui.QProgressDialog(title, "Cancel", 0, BAR_STEPS, FreeCADGui.getMainWindow())
    dialog.setWindowTitle("TemplateQuad")
    dialog.setWindowModality(QtCore.Qt.WindowModal)
    dialog.setMinimumDuration(SHOW_AFTER_MS)
    dialog.setAutoClose(False)
    dialog.setAutoReset(False)
    worker = threading.Thread(target=target, name="TemplateQuad meshing", daemon=True)
    worker.start()
    try:
        while worker.is_alive():
            worker.join(POLL_SECONDS)
            if dialog.wasCanceled():  # the button, Escape, or cancel() from a script
                progress.cancel.set()
            stage, done, total = progress.snapshot()
            if not progress.cancel.is_set():
                dialog.setLabelText(f"{title}: {stage} ({done} of {total})")
            dialog.setValue(min(BAR_STEPS - 1, BAR_STEPS * done // total))
            QtGui.QApplication.processEvents()
        if dialog.wasCanceled():  # pressed during the last events processed
            progress.cancel.set()
    finally:
        dialog.close()
        dialog.deleteLater()
    error = outcome.get("error")
    if error is not None:
        if progress.cancel.is_set() and isinstance(error, meshing.load_tquad().Cancelled):
            return None
        raise error
    if progress.cancel.is_set():
        # Cancel was pressed after the mesher's last look at it (its last stages and
        # the hand-over have none): the user asked for the document as it was.
        return None
    return outcome.get("result")


#: A hand-over of more quads than this shows its own dialog: FreeCAD takes a mesh in
#: C++ calls that answer no event (reading it, copying it into the object, building
#: its view), about 18 microseconds a quad together at ten million quads (bench/GUI_CANCEL.md).
HANDOVER_DIALOG_QUADS = 200_000
#: Seconds FreeCAD takes per quad to take a mesh in (the estimate before a large run).
HANDOVER_SECONDS_PER_QUAD = 18e-6


class HandOver:
    """The steps of handing a finished mesh to FreeCAD, beside a dialog with Cancel.

    Each step() names what comes next and first processes the window's events, so the
    label is painted and a Cancel pressed during the step before is seen; it returns
    False once Cancel was pressed (the caller then keeps the previous mesh). Between
    steps FreeCAD's own calls run and the window does not answer: the label says so.
    """

    def __init__(self, title: str, quads: int, steps: int):
        self.title, self.steps, self.done = title, steps, 0
        self.dialog = None
        if quads > HANDOVER_DIALOG_QUADS:
            self.dialog = QtGui.QProgressDialog(title, "Cancel", 0, steps, FreeCADGui.getMainWindow())
            self.dialog.setWindowTitle("TemplateQuad")
            self.dialog.setWindowModality(QtCore.Qt.WindowModal)
            self.dialog.setMinimumDuration(0)
            self.dialog.setAutoClose(False)
            self.dialog.setAutoReset(False)
            self.seconds = quads * HANDOVER_SECONDS_PER_QUAD

    def step(self, what: str) -> bool:
        if self.dialog is None:
            return True
        self.dialog.setLabelText(f"{self.title}: {what} (step {self.done + 1} of {self.steps}; about "
                                 f"{self.seconds:.0f} s in all, the window does not answer meanwhile)")
        self.dialog.setValue(self.done)
        self.done += 1
        for _ in range(3):  # shown, painted, and any pending Cancel delivered
            QtGui.QApplication.processEvents()
        return not self.dialog.wasCanceled()

    def close(self):
        if self.dialog is not None:
            self.dialog.close()
            self.dialog.deleteLater()
            self.dialog = None
