#pragma once
// The whole public API of madd in one include.
#include "madd/bisect.hpp"
#include "madd/decomposition.hpp"
#include "madd/error.hpp"
#include "madd/geometry.hpp"
#include "madd/graph.hpp"
#include "madd/medial.hpp"
#include "madd/metrics.hpp"
#include "madd/output.hpp"
#include "madd/poly_io.hpp"
#include "madd/predicates.hpp"
#include "madd/pslg.hpp"
#include "madd/triangulation.hpp"
