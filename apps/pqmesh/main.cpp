#include <iostream>

int main() {
  std::cout << "pqmesh 0.1.0\n";
  return 0;
}
