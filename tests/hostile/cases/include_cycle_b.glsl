#include "include_cycle.vert"
