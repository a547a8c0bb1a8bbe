// A simulated Feetech bus: several virtual servos on one wire, each at its own baud rate, with
// broadcast, SYNC READ / SYNC WRITE, reply collisions, reboot silence and a persistent EEPROM file.
#pragma once

#include "feetechpacket.h"
#include "hand.h"
#include "powercut.h"
#include "simrefusal.h"
#include "virtualdevice.h"
#include "virtualfeetechservo.h"

#include <QString>
#include <QVector>

#include <memory>
#include <optional>
#include <vector>

namespace sim {

class VirtualFeetechBus final : public VirtualDevice
{
public:
    // A rebooting servo (instruction 0x08) hears nothing for this long.
    static constexpr qint64 kRebootTimeUs = 500'000;
    static constexpr int kStateFormat = 1;

    struct ServoSpec
    {
        quint8 id = 1;
        QString model; // a model-table name ("STS3215"), "MAJOR/MINOR", or a family ("HLS")
        qint32 baud = 0; // 0: the family's default rate
    };

    // The model a spec names: a model-table name, "major/minor" (e.g. "10/1"), or a family key
    // or name ("hls", "HLS": the family's first listed model, or its generic major/0). Only
    // models with a register table.
    static std::optional<feetech::ModelInfo> resolveModel(QStringView name);
    // Two servos at one ID and one rate answer together, their replies colliding on the wire: a
    // mistake to refuse in a bus description, a case to allow when a test plays it on purpose.
    enum class SharedIds { Refuse, Allow };

    // Unknown model, ID over 253, baud not a code of spec §6, and (unless allowed) two servos
    // with one ID at one baud.
    static bool validate(const QVector<ServoSpec> &specs, SimRefusal *why,
                         SharedIds sharedIds = SharedIds::Refuse);
    static std::unique_ptr<VirtualFeetechBus> create(const QVector<ServoSpec> &specs,
                                                     SimRefusal *why,
                                                     SharedIds sharedIds = SharedIds::Refuse);

    // Specs must have passed validate(); invalid entries are skipped.
    explicit VirtualFeetechBus(const QVector<ServoSpec> &specs);
    VirtualFeetechBus(const VirtualFeetechBus &) = delete;
    VirtualFeetechBus &operator=(const VirtualFeetechBus &) = delete;

    const seriallink::FrameFormat &frameFormat() const override { return m_format; }
    QVector<Response> handleFrame(const QByteArray &frame, qint32 hostBaud, qint64 nowUs) override;
    void advanceTo(qint64 nowUs) override;
    void powerCycle() override;

    int servoCount() const { return int(m_slots.size()); }
    VirtualFeetechServo &servo(int index) { return m_slots.at(size_t(index)).servo; }
    const VirtualFeetechServo &servo(int index) const { return m_slots.at(size_t(index)).servo; }
    VirtualFeetechServo *findServo(quint8 id); // first servo with this ID, any baud
    QVector<int> indexesOf(quint8 id) const; // every servo at this ID, any baud
    // The one servo at `id`; nothing and *why (NoSuchId, SharedId) when none is, or when
    // several share it.
    std::optional<int> uniqueIndexOf(quint8 id, SimRefusal *why) const;
    qint64 nowUs() const { return m_nowUs; } // the time of the last advance or frame
    bool isRebooting(int index, qint64 nowUs) const;

    // Plugs a powered-up servo into the running bus (last in order); it may share an ID with
    // another servo, as a factory-new servo at ID 1 does. False and *why for an invalid spec.
    bool plug(const ServoSpec &spec, SimRefusal *why);
    // Unplugs the servo at `index`; later servos move up one place. It is kept aside, as a servo
    // taken off a bench is, to be plugged back in. False for a bad index.
    bool unplug(int index);
    // The servos unplugged and not plugged back in, the last unplugged last.
    int unpluggedCount() const { return int(m_unplugged.size()); }
    const VirtualFeetechServo &unpluggedServo(int index) const
    {
        return m_unplugged.at(size_t(index)).servo;
    }
    // Plugs the last unplugged servo back in (last in order) as it was, its ID, rate and EEPROM;
    // it starts as after a power-up. False when none was unplugged.
    bool plugBack();
    // Puts the servo at `index` at a new ID, in its RAM and its EEPROM, as a set-up would; two
    // servos may end up sharing one. False and *why (NoSuchPlace, IdOutOfRange) for a bad index or
    // ID.
    bool setServoId(int index, int id, SimRefusal *why);

    // Power, as a bench sees it. An unpowered servo hears and answers nothing and pushes nothing;
    // powered again it starts as after a power cycle. A broken daisy chain after place `index`
    // (-1: whole) takes signal and power from every servo after it.
    bool setPowered(int index, bool powered); // false for a bad index
    // The servo at `index` loses power in the middle of its next EEPROM write sequence (see
    // PowerCut); `power SERVO on` brings it back. False for a bad index.
    bool armPowerCut(int index, PowerCut cut);
    bool isPowered(int index) const; // its own switch and the chain
    bool setChainBreakAfter(int index); // -1 mends; false for an index outside -1..count-1
    int chainBreakAfter() const { return m_chainReach < 0 ? -1 : m_chainReach - 1; }
    // Every servo's supply (one power supply feeds the bus).
    void setSupplyVoltage(double volts);

    // Turns horns whose torque is off; it moves with the bus's time.
    Hand &hand() { return m_hand; }

    // State file: JSON {"format": 1, "servos": [{"model", "eeprom": hex of 256 bytes}...]} in
    // spec order. Loading checks every slot first (count, model, image) and changes nothing on
    // error; then every servo powers up from its image.
    bool loadState(const QString &path, SimRefusal *why);
    bool saveState(const QString &path, SimRefusal *why) const;
    // The same from and to the file's contents; `path` names the file in messages.
    bool loadStateJson(const QByteArray &json, const QString &path, SimRefusal *why);
    QByteArray stateJson() const;
    // When set, the bus saves the state after every frame that changed an EEPROM image.
    void setStatePath(const QString &path);
    QString statePath() const { return m_statePath; }
    QString lastStateError() const { return m_lastStateError; } // of the last automatic save

    // Bytes of simultaneous replies as the wire sees them: wired-AND (the line idles high),
    // padded to the longest.
    static QByteArray collide(const QVector<QByteArray> &frames);

private:
    struct Slot
    {
        VirtualFeetechServo servo;
        qint64 rebootUntilUs = 0;
        quint64 savedRevision = 0;
        bool switchedOn = true;
        PowerCut powerCut = PowerCut::None; // armed by armPowerCut, once
    };

    // Adds a servo; one that shares an ID and rate with servos already there starts with its
    // horn elsewhere, as two real servos would, so their position replies differ on the wire.
    void addSlot(const feetech::ModelInfo &model, quint8 id, qint32 baud);
    bool listens(const Slot &slot, qint32 hostBaud, qint64 nowUs) const;
    bool chainReaches(int index) const;
    // Powers up (a power cycle) the servos that get power back after a change of `wasPowered`.
    void powerUpReturned(const std::vector<bool> &wasPowered);
    std::vector<bool> poweredNow() const;
    void saveIfChanged(bool slotsChanged = false);

    feetech::FrameFormat m_format;
    std::vector<Slot> m_slots;
    std::vector<Slot> m_unplugged; // taken off the bus, as they were
    QString m_statePath;
    QString m_lastStateError;
    qint64 m_nowUs = 0;
    int m_chainReach = -1; // servos at places below it get signal and power; -1: all
    Hand m_hand {*this};
};

} // namespace sim
