// Replays a fuzz target's corpus and crash folders through its LLVMFuzzerTestOneInput: built by
// the normal compiler as a test, it fails (aborts) on the first input that crashes the code or
// breaks one of the target's invariants.
#include "fuzztarget.h"

#include <QDirIterator>
#include <QFile>

#include <cstdio>
#include <vector>

int main(int argc, char **argv)
{
    int replayed = 0;
    for (int i = 1; i < argc; ++i) {
        const QString folder = QFile::decodeName(argv[i]);
        // A target may have no crashes folder yet: nothing to replay there.
        QDirIterator files(folder, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
        while (files.hasNext()) {
            const QString path = files.next();
            QFile file(path);
            if (!file.open(QIODevice::ReadOnly)) {
                std::fprintf(stderr, "cannot read %s: %s\n", qPrintable(path),
                             qPrintable(file.errorString()));
                return 1;
            }
            const QByteArray bytes = file.readAll();
            // A copy the size of the input exactly, as libFuzzer hands it: a read past its end
            // is caught by the sanitizer build.
            std::vector<std::uint8_t> copy(bytes.begin(), bytes.end());
            std::fprintf(stderr, "%s\n", qPrintable(path));
            LLVMFuzzerTestOneInput(copy.data(), copy.size());
            ++replayed;
        }
    }
    std::printf("replayed %d inputs\n", replayed);
    return replayed > 0 ? 0 : 1;
}
