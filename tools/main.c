#include <stdio.h>
#include "shitsukan/core.h"
int main(void) { puts(SK_VERSION_STRING); return 0; }
