// (being written)
#include "link/packetlogmodel.h"
