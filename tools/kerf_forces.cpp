// kerf-forces: placeholder until the analytic CLI lands (issue 2).
int main() { return 0; }
