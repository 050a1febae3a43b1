// The analytic surfaces the harness generates meshes from and measures exact smooth distances on:
// the one place the harness includes them.
#pragma once

#include <tapeline/core/analytic_geodesics.h>
#include <tapeline/core/analytic_surfaces.h>
