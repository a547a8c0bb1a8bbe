// What a port probe heard: whether the port opened, a PTK servo's answer, each Feetech rate's.
#pragma once

#include "portaccess.h"

#include <QMetaType>
#include <QString>
#include <QVector>

namespace feetech {

// What came back at one rate, besides the adapter's echo of the question.
enum class RateHeard {
    Silence, // not a byte
    Unframed, // bytes, but not one valid frame among them
    Frames // valid answers, naming the IDs in `ids`
};

struct RateProbe
{
    qint32 baud = 0;
    RateHeard heard = RateHeard::Silence;
    int bytes = 0; // bytes heard besides the echo
    QVector<quint8> ids; // the IDs of the valid answers (several servos' answers collide)
};

struct PortProbeReport
{
    QString port;
    seriallink::PortAccess access; // problem None: the port opened
    bool cancelled = false;
    bool ptk = false; // a PTK servo answered the query at 115200
    int ptkBytes = 0; // bytes the PTK query heard besides its echo
    bool echo = false; // the adapter sent the questions back (a single-wire adapter)
    QVector<RateProbe> rates; // every Feetech rate asked, fastest first

    bool opened() const { return access.problem == seriallink::PortAccess::Problem::None; }
    // The Feetech rates where anything but the echo came back: the ones worth a scan.
    QVector<qint32> answeringBauds() const;
    // Not a byte besides the echo, at any rate, to any question.
    bool silent() const;
};

} // namespace feetech

Q_DECLARE_METATYPE(feetech::PortProbeReport)
