// A scene header that leaks a render type: check_layers.cmake must refuse it.
#pragma once

#include "render/frame.hpp"
