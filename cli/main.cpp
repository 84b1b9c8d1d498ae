#include "app.hpp"

int main(int argc, char** argv) { return tribolab::cli::run(argc, argv); }
