#include "io/Preset.h"
