// Files a test writes into its temporary folder.
#include "testfiles.h"

#include <QFile>

namespace testsupport {

QString writeTestFile(const QTemporaryDir &dir, const QString &name, const QByteArray &contents)
{
    const QString path = dir.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(contents) != contents.size())
        qFatal("cannot write %s", qPrintable(path));
    return path;
}

} // namespace testsupport
