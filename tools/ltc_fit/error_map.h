// The heat map of an LTC table's fit error (assets/ltc/fit_error.png): cell (i, j) drawn as a
// scale x scale block at column i (roughness 0 at the left, 1 at the right) and row j (normal
// incidence at the top, grazing at the bottom), error / maxError through errorHeatmap's magma
// colormap (image/metrics.h); below it, after a gray gap, a colour bar from 0 (left) to maxError
// (right).
#pragma once
#include "image/image.h"
#include "techniques/common/arealight/ltc_table.h"

namespace rtlab::ltcfit {

Image ltcErrorMap(const LtcTable& table, float maxError, int scale);

} // namespace rtlab::ltcfit
