#include "CameraController.h"
