// The lucent command line (filled in by the render/CLI work).
int main() { return 1; }
