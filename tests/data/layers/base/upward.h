// A base file that includes a later layer: the layer check must fail on it.
#pragma once
#include "scene/ok.h"
