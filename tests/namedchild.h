// Test helper: a page's widget by its object name; a missing one stops the test program.
#pragma once

#include <QObject>
#include <QString>

namespace testsupport {

template<typename T>
T *namedChild(const QObject *parent, const char *name)
{
    T *child = parent->findChild<T *>(QLatin1String(name));
    if (!child)
        qFatal("no widget %s", name);
    return child;
}

} // namespace testsupport
