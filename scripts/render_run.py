#!/usr/bin/python3
"""Pictures of one `igaprep run` output folder, rendered off screen with VTK.

Usage (Debian: python3-vtk9 and xvfb, both installed by scripts/setup.sh):
    xvfb-run -a /usr/bin/python3 scripts/render_run.py OUTPUT_DIR PREFIX [VIEWS]

OUTPUT_DIR is a run's output written with `--keep-intermediate` and the
case's export "vtu" (model.vtu). Writes PREFIX_sides.png (T1 coloured by
cut region, with the cut loops), PREFIX_midsurface.png (M0trim coloured by
u), PREFIX_patches.png (the model coloured by patch, T1 translucent),
PREFIX_quality.png (its surface coloured by each element's smallest sampled
scaled Jacobian, with a colour bar), for a model of more than one
material PREFIX_materials.png, and for each T-NURCC surface in
OUTPUT_DIR/tnurcc (`igaprep tnurcc ... -o OUTPUT_DIR/tnurcc`, or a case's
"tnurcc" section) PREFIX_tnurcc_NAME.png (the limit surface coloured by
mean curvature, its cage as a wireframe), each from
above and from an oblique view, or from the directions VIEWS gives
("x,y,z;x,y,z;...", the camera's direction from the model's centre).
"""
import math
import os
import sys

import vtk


def read(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def actor(data, array=None, colour=(0.75, 0.75, 0.75), opacity=1.0, line_width=1.0):
    surface = vtk.vtkDataSetSurfaceFilter()
    surface.SetInputData(data)
    if data.GetCellData().GetArray("HigherOrderDegrees") is not None:
        surface.SetNonlinearSubdivisionLevel(2)  # Bezier cells drawn curved
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(surface.GetOutputPort())
    mapper.ScalarVisibilityOff()
    if array:
        cells = data.GetCellData().GetArray(array)
        values = cells if cells is not None else data.GetPointData().GetArray(array)
        if cells is not None:
            mapper.SetScalarModeToUseCellFieldData()
        else:
            mapper.SetScalarModeToUsePointFieldData()
        mapper.SelectColorArray(array)
        mapper.SetScalarRange(values.GetRange())
        mapper.ScalarVisibilityOn()
    a = vtk.vtkActor()
    a.SetMapper(mapper)
    a.GetProperty().SetColor(*colour)
    a.GetProperty().SetOpacity(opacity)
    a.GetProperty().SetLineWidth(line_width)
    return a


# From above and from an oblique view, when no VIEWS are given.
DEFAULT_VIEWS = ((0, 0, 1), (1, -1, 0.6))


def cage_actor(path):
    reader = vtk.vtkOBJReader()
    reader.SetFileName(path)
    edges = vtk.vtkExtractEdges()
    edges.SetInputConnection(reader.GetOutputPort())
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(edges.GetOutputPort())
    mapper.ScalarVisibilityOff()
    a = vtk.vtkActor()
    a.SetMapper(mapper)
    a.GetProperty().SetColor(0.1, 0.1, 0.1)
    a.GetProperty().SetOpacity(0.35)
    return a


def percentile_range(values, low=0.01, high=0.99):
    """The 1st and 99th percentile of an array's finite values: the colours
    are not spent on a few points (the curvature at extraordinary points)."""
    finite = sorted(v for v in (values.GetValue(i) for i in range(values.GetNumberOfTuples())) if math.isfinite(v))
    return finite[int(low * (len(finite) - 1))], finite[int(high * (len(finite) - 1))]


def render_tnurcc(folder, prefix, views):
    tnurcc = os.path.join(folder, "tnurcc")
    if not os.path.isdir(tnurcc):
        return
    for name in sorted(f[: -len("_limit.vtu")] for f in os.listdir(tnurcc) if f.endswith("_limit.vtu")):
        data = read(os.path.join(tnurcc, name + "_limit.vtu"))
        limit = actor(data, "MeanCurvature")
        limit.GetMapper().SetScalarRange(*percentile_range(data.GetPointData().GetArray("MeanCurvature")))
        cage = cage_actor(os.path.join(tnurcc, name + "_cage.obj"))
        render([limit, cage], prefix + "_tnurcc_" + name + ".png", views, [colour_bar(limit, "mean curvature")])


def colour_bar(a, title):
    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(a.GetMapper().GetLookupTable())
    bar.SetTitle(title)
    bar.SetNumberOfLabels(5)
    for text in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
        text.SetColor(0, 0, 0)
    return bar


def render(actors, path, views=DEFAULT_VIEWS, overlays=()):
    renderer = vtk.vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    for a in actors:
        renderer.AddActor(a)
    for o in overlays:
        renderer.AddActor2D(o)
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(900, 600)
    images = vtk.vtkImageAppend()
    images.SetAppendAxis(0)
    for view in views:
        renderer.ResetCamera()
        camera = renderer.GetActiveCamera()
        focal, distance = camera.GetFocalPoint(), camera.GetDistance()
        camera.SetPosition(*(focal[k] + view[k] * distance for k in range(3)))
        camera.SetViewUp(*((0, 1, 0) if abs(view[2]) > 0.9 else (0, 0, 1)))
        renderer.ResetCamera()
        window.Render()
        grab = vtk.vtkWindowToImageFilter()
        grab.SetInput(window)
        grab.Update()
        image = vtk.vtkImageData()
        image.DeepCopy(grab.GetOutput())
        images.AddInputData(image)
    images.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(images.GetOutput())
    writer.Write()


def parse_views(text):
    views = [tuple(float(x) for x in view.split(",")) for view in text.split(";")]
    if any(len(v) != 3 or not any(v) for v in views):
        sys.exit("VIEWS: directions x,y,z (not all zero) separated by ';', got " + text)
    return tuple(views)


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    folder, prefix = sys.argv[1], sys.argv[2]
    views = parse_views(sys.argv[3]) if len(sys.argv) == 4 else DEFAULT_VIEWS
    regions = os.path.join(folder, "midsurface_t1_regions.vtu")
    loops = os.path.join(folder, "midsurface_loops.vtu")
    if os.path.exists(regions):
        render([actor(read(regions), "region"), actor(read(loops), colour=(0, 0, 0), line_width=3)],
               prefix + "_sides.png", views)
        render([actor(read(os.path.join(folder, "midsurface_m0trim.vtu")), "u")], prefix + "_midsurface.png", views)
    model = os.path.join(folder, "model.vtu")
    if os.path.exists(model):
        shell = [actor(read(regions), opacity=0.25)] if os.path.exists(regions) else []
        data = read(model)
        render([actor(data, "patch")] + shell, prefix + "_patches.png", views)
        if data.GetCellData().GetArray("min_scaled_jacobian") is not None:
            quality = actor(data, "min_scaled_jacobian")
            render([quality], prefix + "_quality.png", views, [colour_bar(quality, "scaled Jacobian")])
        materials = data.GetCellData().GetArray("material")
        if materials is not None and materials.GetRange()[1] > materials.GetRange()[0]:
            render([actor(data, "material")], prefix + "_materials.png", views)
    render_tnurcc(folder, prefix, views)


if __name__ == "__main__":
    main()
