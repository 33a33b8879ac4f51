// SPDX-License-Identifier: BSL-1.0
// locus_gallery <out_dir>: writes every gallery figure as <out_dir>/fig_<chapter>_<n>.svg and an
// index.html listing them with the book's captions. Exit code 0 when every figure was computed
// and written, 1 otherwise (the failures are listed on stderr).
#include "gallery.hpp"

#include <iostream>
#include <string>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: locus_gallery <out_dir>\n";
    return 2;
  }
  const locus_gallery::RunResult r = locus_gallery::run(argv[1]);
  for (const std::string& e : r.errors) std::cerr << "locus_gallery: " << e << "\n";
  std::cout << "locus_gallery: wrote " << r.written << " figures to " << argv[1] << "\n";
  return r.status == locus::Status::ok ? 0 : 1;
}
