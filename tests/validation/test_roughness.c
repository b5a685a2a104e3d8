#include <stdio.h>
int main(void) { puts("test_roughness: not written yet"); return 1; }
