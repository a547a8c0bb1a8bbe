// Feetech register tables, loaded from JSON data and validated.
#pragma once

#include "feetechvalue.h"
#include "tablefacts.h"

#include <QString>
#include <QStringView>
#include <QVector>

#include <optional>

namespace feetech {

enum class Family { Scs, Sts, Sms, Hls };
constexpr Family kAllFamilies[] = {Family::Scs, Family::Sts, Family::Sms, Family::Hls};

QString familyKey(Family family); // "scs", "sts", "sms", "hls"
QString familyName(Family family); // "SCS", "STS", ...

// A text of a shipped register table (a label, choice, bit name, note or unit) in the user's
// language. The tables hold English, which the code also matches on ("Load"); only what is shown
// goes through this. resources/translations/datastrings.cpp lists the texts for lupdate.
QString tableText(const QString &english);
// A unit ("step", "step/s²", "V") in the user's language: the one place a unit is translated, so
// the Memory table, the Control and Monitor pages and servoctl name a unit alike.
QString unitText(const QString &english);
std::optional<Family> familyFromKey(QStringView key);

enum class Storage { Eeprom, Ram };
enum class Access { ReadOnly, ReadWrite };

struct Choice
{
    qint32 value = 0;
    QString label;
};

struct BitName
{
    int bit = 0;
    QString label;
};

struct Register
{
    int address = 0;
    int size = 1;
    QString key;
    QString label;
    Storage storage = Storage::Ram;
    Access access = Access::ReadOnly;
    QString unit;
    double scale = 1.0;
    qint32 minimum = 0; // register units (decoded, signed where signBit is set)
    qint32 maximum = 0;
    std::optional<int> signBit;
    std::optional<qint32> defaultValue;
    QVector<Choice> choices;
    QVector<BitName> bits;
    QString note;

    int end() const { return address + size; } // one past the last address
    // Whether bytes [from, from + count) touch this register.
    bool overlaps(int from, int count) const { return from < end() && address < from + count; }
    bool writable() const { return access == Access::ReadWrite; }
};

// A run of registers with no gap between them: one READ covers it.
struct Block
{
    int address = 0;
    int size = 0;
};

class RegisterTable
{
public:
    // Parses and validates a table; on failure returns nothing and says why in *error, naming
    // `source` and the register at fault.
    static std::optional<RegisterTable> fromJson(const QByteArray &json, const QString &source,
                                                 QString *error);
    // The table compiled into the application for a family (loaded once).
    static const RegisterTable &forFamily(Family family);
    // A servo whose model no table describes: `size` read-only bytes from address 0, shown as
    // they are, never interpreted.
    static const RegisterTable &rawView();
    static constexpr int kRawViewSize = 87; // addresses 0-86: what every known table spans

    Family family() const { return m_family; }
    bool isRaw() const { return m_raw; }
    const QString &title() const { return m_title; }
    ByteOrder byteOrder() const { return m_byteOrder; }
    const QVector<Register> &registers() const { return m_registers; }

    const Register *find(QStringView key) const;
    const Register *at(int address) const; // the register starting at this address
    ValueFormat format(const Register &reg) const { return {reg.size, m_byteOrder, reg.signBit}; }
    QVector<Block> blocks() const;
    // The RAM registers in runs without gaps (a block of blocks() may begin in EEPROM and go
    // on into RAM): what a background refresh reads.
    QVector<Block> ramBlocks() const;
    // The value torque_enable takes for `mode`; none where the family lacks it.
    std::optional<qint32> torqueValue(TorqueMode mode) const
    {
        return m_facts.torqueValues[std::size_t(mode)];
    }
    // What a torque_enable value means here; none for a value the table gives no meaning.
    std::optional<TorqueMode> torqueMode(qint64 value) const;
    // Present position through present current: what one telemetry read fetches.
    Block feedbackBlock() const { return {m_facts.feedbackAddress, m_facts.feedbackSize}; }

private:
    Family m_family = Family::Sts;
    QString m_title;
    ByteOrder m_byteOrder = ByteOrder::Little;
    QVector<Register> m_registers; // ascending addresses, no overlaps
    TableFacts m_facts;
    bool m_raw = false;
};

qint32 defaultBaud(Family family); // the factory rate its table gives (SMS 115200, others 1 Mbps)
// A rate as people read it: "1 Mbps", "115,200 bps" (translated, in the user's locale).
QString baudText(qint32 baud);

} // namespace feetech
