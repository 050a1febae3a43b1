// The analytic surfaces the harness generates meshes from and measures exact smooth distances on:
// the one place the harness includes them.
#pragma once

#include <tapeline/surfaces/analytic_geodesics.h>
#include <tapeline/surfaces/analytic_surfaces.h>
