#include <stdio.h>
int main(void) { puts("test_cohesion: not written yet"); return 1; }
