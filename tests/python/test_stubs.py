"""The type stubs (tquad/__init__.pyi) against the package they describe: a keyword,
an attribute or a public name added to the module and not to the stubs fails here."""
import ast
import inspect
import os
import sys
import unittest

import numpy as np

import tquad

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import generate_stubs  # noqa: E402


def stub_tree():
    path = os.path.join(os.path.dirname(tquad.__file__), "__init__.pyi")
    with open(path) as f:
        return ast.parse(f.read(), path)


def stub_functions(tree):
    return {node.name: node for node in tree.body if isinstance(node, ast.FunctionDef)}


def stub_class(tree, name):
    return next(node for node in tree.body if isinstance(node, ast.ClassDef) and node.name == name)


def stub_parameters(node):
    """(name, kind, has default) per parameter of a stub's def, in order."""
    a = node.args
    positional = a.posonlyargs + a.args
    with_default = len(a.defaults)
    out = [(p.arg, "positional", i >= len(positional) - with_default) for i, p in enumerate(positional)]
    out += [(p.arg, "keyword", d is not None) for p, d in zip(a.kwonlyargs, a.kw_defaults)]
    return out


def real_parameters(function):
    out = []
    for p in inspect.signature(function).parameters.values():
        kind = "keyword" if p.kind == inspect.Parameter.KEYWORD_ONLY else "positional"
        out.append((p.name, kind, p.default is not inspect.Parameter.empty))
    return out


class StubsMatchTheModule(unittest.TestCase):
    def setUp(self):
        self.tree = stub_tree()

    def test_public_names(self):
        stub_all = next(node.value for node in self.tree.body
                        if isinstance(node, ast.Assign) and node.targets[0].id == "__all__")
        self.assertEqual(sorted(ast.literal_eval(stub_all)), sorted(tquad.__all__))

    def test_function_parameters(self):
        functions = stub_functions(self.tree)
        for name in tquad.__all__:
            real = getattr(tquad, name)
            if not inspect.isfunction(real):
                continue
            with self.subTest(function=name):
                self.assertIn(name, functions)
                self.assertEqual(stub_parameters(functions[name]), real_parameters(real))

    def test_mesh_shape_is_generated_from_the_options_schema(self):
        path = os.path.join(os.path.dirname(tquad.__file__), "__init__.pyi")
        with open(path) as f:
            text = f.read()
        self.assertEqual(generate_stubs.stub_with_schema(text, tquad.mesh_option_schema()), text,
                         "run scripts/generate_stubs.py")

    def test_mesh_attributes(self):
        square = [(0, 0), (1, 0), (2, 0), (2, 1), (2, 2), (1, 2), (0, 2), (0, 1)]
        mesh = tquad.mesh_boundary(np.array(square, dtype=float), corners=[0, 2, 4, 6])
        stub = stub_class(self.tree, "Mesh")
        annotated = {node.target.id for node in stub.body if isinstance(node, ast.AnnAssign)}
        self.assertEqual(annotated, set(vars(mesh)))
        methods = {node.name for node in stub.body if isinstance(node, ast.FunctionDef)}
        public = {n for n, v in inspect.getmembers(tquad.Mesh) if not n.startswith("_")}
        self.assertEqual(methods - {"__init__"}, public)


if __name__ == "__main__":
    unittest.main()
