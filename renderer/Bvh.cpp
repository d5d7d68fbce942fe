#include "Bvh.h"
