// (being written)
#include "packetlogdock.h"
