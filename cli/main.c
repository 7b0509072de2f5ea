#include <stdio.h>
#include "qdot/qdot.h"
int main(void) { printf("qdot %s\n", QDOT_VERSION); return 0; }
