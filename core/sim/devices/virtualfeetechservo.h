// One simulated Feetech serial-bus servo: register file, EEPROM lock and instructions, driving
// its motor (virtualfeetechmotor.h). Pure logic: no I/O, no timers; time passes through
// advanceTo().
#pragma once

#include "feetechpacket.h"
#include "modeltable.h"
#include "registertable.h"
#include "virtualfeetechmotor.h"

#include <QByteArray>
#include <QString>
#include <QStringView>

#include <array>
#include <optional>

namespace sim {

class VirtualFeetechServo
{
public:
    static constexpr int kRegisterFileSize = 256;

    // Supply defaults: a 2S LiPo (HLS: a 12 V supply).
    static constexpr double kDefaultSupplyVolts = 7.4;
    static constexpr double kDefaultHlsSupplyVolts = 12.0;

    // Baud-rate codes 0-7 of spec §6.
    static std::optional<int> baudCode(qint32 baud);
    static qint32 baudForCode(int code); // 0 for a code outside 0-7
    static qint32 defaultBaud(feetech::Family family); // SMS 115200, others 1000000

    // `model.family` must be set and `baud` one of the codes' rates (otherwise the family's
    // default is used).
    VirtualFeetechServo(const feetech::ModelInfo &model, quint8 id, qint32 baud);

    feetech::Family family() const { return m_table->family(); }
    QString modelName() const { return m_model.name; }
    const feetech::ModelInfo &model() const { return m_model; }
    const feetech::RegisterTable &table() const { return *m_table; }

    // Live values: an ID or baud change takes effect as soon as it is written.
    quint8 id() const;
    qint32 baudRate() const;
    // HLS "secondary ID" (address 7) when set and different from the ID: write, reg-write,
    // action and sync-write addressed to it are executed without a reply.
    std::optional<quint8> secondaryId() const;
    // Silence before a reply: register 7 × 2 µs (SMS: at least 100 µs); 0 where 7 is no delay.
    qint64 returnDelayUs() const;
    bool answersSyncRead() const { return family() != feetech::Family::Scs; }

    // An instruction addressed to this servo (by ID, or broadcast): the status packet to send,
    // if any. SYNC READ / SYNC WRITE are the bus's business (see below).
    std::optional<QByteArray> execute(const feetech::Packet &packet, bool broadcast);
    // One SYNC WRITE entry for this servo: a write without a reply.
    void applySyncWrite(quint8 address, const QByteArray &data);
    // The READ status frame for `length` bytes at `address`, or nothing when the range is invalid.
    std::optional<QByteArray> readReply(int address, int length) const;
    // Firmware that answers no READ longer than `bytes` (tests of the host's fallback); by
    // default any READ that fits in a packet is answered.
    void setLongestRead(int bytes) { m_longestRead = bytes; }

    void advanceTo(qint64 nowUs);
    qint64 nowUs() const { return m_nowUs; }

    // EEPROM values reload from the image, RAM returns to power-on values, lock = 1.
    void powerCycle();

    // The persistent EEPROM: 256 bytes laid out like the register file, RAM bytes zero.
    QByteArray eepromImage() const { return m_image; }
    // Replaces the writable EEPROM bytes (read-only factory bytes are kept); takes effect at the
    // next powerCycle(). False when the image is not 256 bytes.
    bool setEepromImage(const QByteArray &image);
    // Counts changes of the image, so the bus can save the state file when it moves.
    quint64 eepromRevision() const { return m_eepromRevision; }

    // Environment hooks.
    void setSupplyVoltage(double volts);
    void setAmbientTemperature(double celsius);
    void setExternalLoad(int permille); // signed, ±1000; |load| ≥ torque limit blocks the horn
    void setTemperature(double celsius);
    void setPhysicalPosition(double steps); // puts the horn there at once
    // The hand turns the horn: at `steps`, going `stepsPerSecond` now (present speed, moving).
    void turnByHand(double steps, double stepsPerSecond);
    // The motor warms by this much a second on top of its own heating, until set to 0; at its
    // maximum temperature it trips as a real one does (torque off, status bit 0x04).
    void setTemperatureRise(double celsiusPerSecond)
    {
        m_motor.motion().setTemperatureRise(celsiusPerSecond);
    }
    double temperatureRise() const { return m_motor.motion().temperatureRise(); }
    // A latched overload: status bit 0x20 stays set and the motor stays limp even when torque is
    // switched on again; only a power cycle clears it.
    void setOverloadLatched(bool latched);
    bool overloadLatched() const { return m_motor.motion().overloadLatched(); }
    int externalLoad() const { return m_motor.motion().externalLoad(); }
    double supplyVoltage() const { return m_motor.motion().supplyVoltage(); }
    double temperature() const { return m_motor.motion().temperature(); }
    double physicalPosition() const { return m_motor.motion().position(); }

    // Test hooks: decoded register units; setValue writes the live register, no lock semantics.
    qint32 value(QStringView key) const;
    void setValue(QStringView key, qint32 value);
    // As an unlocked host write: an EEPROM register keeps the value across power cycles, a RAM
    // register until the next one. For set-up scenes (a robot's settings, a servo put at an ID).
    void storeValue(QStringView key, qint32 value);
    const QByteArray &registerFile() const { return m_registers; }

private:
    struct Keys
    {
        const feetech::Register *id = nullptr;
        const feetech::Register *baud = nullptr;
        const feetech::Register *returnDelay = nullptr;
        const feetech::Register *secondaryId = nullptr;
        const feetech::Register *responseLevel = nullptr;
        const feetech::Register *maxTorque = nullptr;
        const feetech::Register *protectionCurrent = nullptr;
        const feetech::Register *offset = nullptr;
        const feetech::Register *mode = nullptr;
        const feetech::Register *torqueEnable = nullptr;
        const feetech::Register *goalPosition = nullptr;
        const feetech::Register *goalTime = nullptr; // 44: time / PWM / HLS goal current
        const feetech::Register *torqueLimit = nullptr;
        const feetech::Register *lock = nullptr;
        const feetech::Register *presentPosition = nullptr;
        const feetech::Register *presentSpeed = nullptr;
        const feetech::Register *presentLoad = nullptr;
        const feetech::Register *presentVoltage = nullptr;
        const feetech::Register *presentTemperature = nullptr;
        const feetech::Register *asyncFlag = nullptr;
        const feetech::Register *status = nullptr;
        const feetech::Register *moving = nullptr;
        const feetech::Register *currentGoal = nullptr;
        const feetech::Register *presentCurrent = nullptr;
    };

    struct PendingWrite
    {
        quint8 address = 0;
        QByteArray data;
    };

    qint32 get(const feetech::Register *reg) const;
    void put(const feetech::Register *reg, qint32 value); // clamps to what the format holds
    void putRegisterBytes(const feetech::Register &reg, const QByteArray &from, QByteArray &to);
    void store(const feetech::Register *reg, qint32 value); // a host write: lock semantics
    void keepInImage(const feetech::Register &reg); // the live bytes become the EEPROM's
    bool unlocked() const;
    bool replies(quint8 instruction, bool broadcast) const;
    QByteArray statusReply(quint8 replyId, const QByteArray &data = {}) const;

    void applyWrite(int address, QByteArrayView data);
    bool acceptable(const feetech::Register &reg, qint32 value) const;
    void recover();
    bool calibrate(const QByteArray &parameters);
    void calibratePresentTo(qint32 target);

    const feetech::RegisterTable *m_table = nullptr;
    feetech::ModelInfo m_model;
    Keys m_keys;
    std::array<const feetech::Register *, kRegisterFileSize> m_byAddress {};

    QByteArray m_registers = QByteArray(kRegisterFileSize, '\0');
    QByteArray m_powerOnRam = QByteArray(kRegisterFileSize, '\0');
    QByteArray m_image = QByteArray(kRegisterFileSize, '\0');
    int m_longestRead = kRegisterFileSize;
    QByteArray m_factory = QByteArray(kRegisterFileSize, '\0');
    std::optional<QByteArray> m_backup;
    quint64 m_eepromRevision = 0;
    std::optional<PendingWrite> m_pending;

    VirtualFeetechMotor m_motor;
    qint64 m_nowUs = 0;
};

} // namespace sim
