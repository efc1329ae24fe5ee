"""StatelessProxy: base of the add-on's proxies, which keep nothing worth saving.

FreeCAD saves a proxy's state with the document. Python 3.11 gives every object a
default __getstate__ that would save attributes such as a last error message; these
methods make FreeCAD save nothing (the file stores "null") and restore nothing.
"""


class StatelessProxy:
    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None

    def dumps(self):
        return None

    def loads(self, state):
        return None
