#include "igaprep/export/pvd.h"

#include "igaprep/core/atomic_file.h"
#include "igaprep/core/error.h"
#include "igaprep/core/text.h"
#include "xml_text.h"

namespace igaprep::exporter {

void write_pvd(const std::string& path, const std::vector<std::string>& files) {
  for (const std::string& f : files)
    if (invalid_text_at(f) != std::string::npos) throw bad_input("'" + path + "': a file name is not UTF-8 text");
  write_file_atomically(path, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n <Collection>\n";
    for (std::size_t i = 0; i < files.size(); ++i)
      out << "  <DataSet part=\"" << i << "\" file=\"" << detail::xml_escape(files[i]) << "\"/>\n";
    out << " </Collection>\n</VTKFile>\n";
  });
}

}  // namespace igaprep::exporter
