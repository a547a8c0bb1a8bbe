// (being written)
#include "ptkpage.h"
