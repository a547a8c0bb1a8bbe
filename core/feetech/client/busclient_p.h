// The bus client's inside: the operations submitted and not finished, the scan, the clock that
// stamps the values read; only BusClient sees it.
#pragma once

#include "busclient.h"

#include <QElapsedTimer>

#include <algorithm>
#include <map>

namespace feetech {

struct BusClientPrivate
{
    // An operation submitted and not finished: the servo it works on (by its address before it
    // ran, and after each step of an apply chain), its kind and reply. The link going down
    // leaves it `dropped` (no longer busy) until the session reports its end.
    struct Pending
    {
        quint8 id = 0;
        qint32 baud = 0;
        BusClient::Work kind = BusClient::Work::Foreground;
        OperationReply *reply = nullptr;
        bool dropped = false;
    };
    std::map<quint64, Pending> pending; // by ticket
    quint64 lastTicket = 0;
    bool scanning = false;
    QElapsedTimer clock;

    // Whether an operation not dropped is on its way (a background refresh waits for none).
    bool hasLivePending() const
    {
        return std::any_of(pending.begin(), pending.end(),
                           [](const auto &entry) { return !entry.second.dropped; });
    }
};

} // namespace feetech
