#pragma once
// Everything of the spline core in one include.
#include "igaprep/spline/basis.h"
#include "igaprep/spline/bezier_extraction.h"
#include "igaprep/spline/curve_surface.h"
#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/fit.h"
#include "igaprep/spline/gauss_legendre.h"
#include "igaprep/spline/knot_removal.h"
#include "igaprep/spline/knot_vector.h"
#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/multipatch_topology.h"
#include "igaprep/spline/refine.h"
#include "igaprep/spline/scaled_jacobian.h"
