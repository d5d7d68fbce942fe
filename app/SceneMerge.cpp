#include "SceneMerge.h"
