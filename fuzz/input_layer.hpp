#pragma once

// The headers of sweetspot's input layer that the fuzz targets drive, in one
// place: when the layer's headers move, this is the only list to update.

#include "io/design_reader.hpp"
#include "io/input_error.hpp"
#include "io/json_reader.hpp"
#include "studies/batch.hpp"
#include "studies/study.hpp"
#include "sweetspot/evaluate.hpp"
