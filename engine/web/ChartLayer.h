#pragma once

#include "charts/Chart.h"

#include <QJsonObject>

#include <vector>

namespace neptus::web {

// The chart layer the live web page draws: the features, depth shades and
// safety contour the console's map draws (charts::drawnAs, depthShade,
// safetyContour), of the features that meet the box, in degrees as the page's
// JSON:
//   {"cells": ["US4MD81M", …], "safetyContour": 6,
//    "layers": [{"band": 4,
//                "areas": {"deep": [polygon, …], "medium", "shallow", "drying", "land"},
//                "lines": {"contour": [polyline, …], "safety", "coast", "restricted", "fairway"}}, …],
//    "marks": [{"kind": "hazard"|"buoy"|"beacon"|"light",
//               "shape": "cross"|"flare"|"conical"|"can"|… (charts::shapeName), "lat", "lon",
//               "scamin", "what": "wreck", "name", "depth",
//               "colour": "red"|"green"|"yellow" (an aid's charted colour)}, …]}
// A layer is what the cells of one usage band draw, overview first: drawn in
// that order (each layer's areas, then its lines), the best band covers the
// rest where cells overlap (charts::drawingOrder); a mark is left out where a
// better band covers it. A polygon is a list of rings (even-odd), a ring or polyline a list of
// [lat, lon]. Points nearer than `tolerance` degrees to the last one kept are
// left out (about a pixel of the page's view), and positions are rounded to
// 1e-6° (10 cm).
QJsonObject chartLayer(const std::vector<charts::Cell> &cells, double west, double south, double east, double north,
                       double safetyDepth, double tolerance);

} // namespace neptus::web
