#include "ObjLoader.h"
