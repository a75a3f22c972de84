#pragma once

// The headers of sweetspot's input layer that the fuzz targets drive, in one
// place: when the layer's headers move, this is the only list to update.

#include "sweetspot/evaluate.hpp"
#include "sweetspot/io/batch.hpp"
#include "sweetspot/io/design_reader.hpp"
#include "sweetspot/io/input_error.hpp"
#include "sweetspot/io/json_reader.hpp"
#include "sweetspot/io/study.hpp"
