#pragma once
#include "base/vec.h"
