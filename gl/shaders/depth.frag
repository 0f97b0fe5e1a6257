// Light views that only make a shadow map: depth is all that is written.
void main() {}
