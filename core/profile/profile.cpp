// (being written)
#include "profile/profile.h"
