// Must compile: the control of Layers.*, which shows the probes' failures come from the rule alone.
#include <ptview/scene/Scene.h>
