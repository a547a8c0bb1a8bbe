// Files a test writes into its temporary folder.
#pragma once

#include <QByteArray>
#include <QString>
#include <QTemporaryDir>

namespace testsupport {

// Writes `contents` to `name` in `dir`; its path. A file that cannot be written ends the test
// run: nothing a test checks afterwards would mean anything.
QString writeTestFile(const QTemporaryDir &dir, const QString &name, const QByteArray &contents);

} // namespace testsupport
