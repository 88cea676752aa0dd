// libFuzzer harness: the E57 reader (io/E57PagedFile.cpp, E57Structure.cpp, E57VectorReader.cpp,
// E57Reader.cpp), through io::openPointReader as stylos-cli and the workbench read a .e57 file, every batch
// to the end. The page CRCs are recomputed first so that mutations reach the XML section and the compressed
// vectors (the CRC check itself is covered by E57ReaderTest). Inputs of odd length are read in an import
// frame (+Y up, millimetres: the FramedReader) and only scan 0.
#include "FuzzSupport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace stylos;
    const std::vector<std::uint8_t> bytes = fuzz::withE57Checksums(data, size);
    core::io::ReadOptions options;
    if (size % 2 == 1) {
        options.frame = {core::io::UpAxis::PosY, core::io::LengthUnit::Millimetre, {0.0, 0.0, 0.0}};
        options.scan = 0;
    }
    fuzz::readAllPoints(fuzz::writeScratch(bytes.data(), bytes.size(), "e57"), options);
    return 0;
}
