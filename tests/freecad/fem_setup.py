"""The FEM analysis the CalculiX tests share: an analysis with a static, linear
CalculiX (ccxtools) solver and a steel material (E = 210000 MPa, nu = 0.3)."""


def steel_analysis(doc):
    """(analysis, solver) in doc, the solver and the material already in the analysis."""
    import ObjectsFem

    analysis = ObjectsFem.makeAnalysis(doc, "Analysis")
    solver = ObjectsFem.makeSolverCalculixCcxTools(doc, "CalculiX")
    solver.AnalysisType = "static"
    solver.GeometricalNonlinearity = "linear"
    analysis.addObject(solver)
    material = ObjectsFem.makeMaterialSolid(doc, "Steel")
    values = material.Material
    values.update({"Name": "Steel", "YoungsModulus": "210000 MPa", "PoissonRatio": "0.30"})
    material.Material = values
    analysis.addObject(material)
    return analysis, solver
