#include "ViewerScript.h"
