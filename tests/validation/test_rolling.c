#include <stdio.h>
int main(void) { puts("test_rolling: not written yet"); return 1; }
