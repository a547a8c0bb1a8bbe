// Hex frames from spec/ptk-protocol.md and the Feetech seed: the tests' known answers.
#pragma once

#include <QByteArray>
#include <QVector>

#include <array>

namespace specvectors {

struct PtkExchange
{
    const char *name;
    int command;
    const char *query;
    const char *reply;
};

// The eight query -> reply exchanges of the seed, in PTK's polling order.
inline const std::array<PtkExchange, 8> kPtkExchanges {{
    {"N1", 0x38, "AFFA000A3800000000 42", "AFFA0009032007D0 03"},
    {"N2", 0x3D, "AFFA000A3D00000000 47", "AFFA0009001D000C 32"},
    {"N3", 0x3F, "AFFA000A3F00000000 49", "AFFA000904B00000 BD"},
    {"N4", 0x50, "AFFA000A5000000000 5A", "AFFA000907D02710 17"},
    {"N5", 0x51, "AFFA000A5100000000 5B", "AFFA000900410041 8B"},
    {"N6", 0x52, "AFFA000A5200000000 5C", "AFFA000910000000 19"},
    {"N7", 0x53, "AFFA000A5300000000 5D", "AFFA0009000F0000 18"},
    {"N8", 0x54, "AFFA000A5400000000 5E", "AFFA000900010000 0A"},
}};

// The twelve write frames, N1..N12 in order, for the seed's values with soft start = 1.
inline const std::array<const char *, 12> kPtkWrites {{
    "AFFA000A01001D0000 28",
    "AFFA000A05000C0000 1B",
    "AFFA000A12032007D0 16",
    "AFFA000A1804B00000 D6",
    "AFFA000A4000000041 8B",
    "AFFA000A4100000041 8C",
    "AFFA000A4200001000 5C",
    "AFFA000A430000000F 5C",
    "AFFA000A4400000001 4F",
    "AFFA000A4500000000 4F",
    "AFFA000A4807D02710 60",
    "AFFA000A4600000001 51",
}};

inline QByteArray bytes(const char *hex)
{
    return QByteArray::fromHex(QByteArray(hex).replace(' ', ""));
}

// Query, echo-free: every query followed by its reply, as a sniffer on the servo side sees it.
inline QByteArray ptkConversation(bool withEcho)
{
    QByteArray stream;
    for (const PtkExchange &exchange : kPtkExchanges) {
        if (withEcho)
            stream += bytes(exchange.query);
        stream += bytes(exchange.reply);
    }
    return stream;
}

} // namespace specvectors
