#include "tsis_shared.h"
