// The health check's reads: limits in one READ, then repeated feedback reads with the link's
// counters taken before and after, so each servo's retries, timeouts and checksum errors are
// its own.
#include "healthcheck.h"

#include "feetechsessiontr.h"
#include "feetechvalue.h"
#include "linksession.h"
#include "registerkeys.h"

#include <QCoreApplication>

#include <algorithm>

namespace feetech {

using namespace registerkeys;

namespace {

// The registers the verdict needs, all in EEPROM near the start of every family's table.
const QStringList kLimitKeys {QStringLiteral("firmware_major"),
                              QStringLiteral("firmware_minor"),
                              kMinAngleLimit,
                              kMaxAngleLimit,
                              QStringLiteral("max_temperature"),
                              QStringLiteral("max_voltage"),
                              QStringLiteral("min_voltage"),
                              QStringLiteral("overload_torque")};

Exchange readExchange(const ServoInfo &servo, int address, int size)
{
    Exchange ask;
    ask.request = feetech::read(servo.id, quint8(address), quint8(size));
    ask.replyId = servo.id;
    ask.replyDataSize = size;
    return ask;
}

} // namespace

struct HealthCheck::Run
{
    HealthReading reading;
    int reads = 0;
    std::function<void(const HealthReading &)> done;
    seriallink::LinkCounters before;
};

HealthCheck::HealthCheck(BusExchange &bus, QObject *parent)
    : QObject(parent)
    , m_bus(bus)
{ }

void HealthCheck::read(const ServoInfo &servo, int reads,
                       std::function<void(const HealthReading &)> done)
{
    auto run = std::make_shared<Run>();
    run->reading.servo = servo;
    run->reads = std::max(reads, 1);
    run->done = std::move(done);
    m_bus.setBaud(servo.baud)([this, run](bool ok, const QString &message) {
        if (!ok) {
            run->reading.failure = message;
            run->done(run->reading);
            return;
        }
        readLimits(run);
    });
}

void HealthCheck::readLimits(std::shared_ptr<Run> run)
{
    const ServoInfo &servo = run->reading.servo;
    if (!servo.hasTable()) {
        readFeedback(run); // an unknown model: its answers are all that can be judged
        return;
    }
    const RegisterTable &table = servo.table();
    QVector<const Register *> registers;
    for (const QString &key : kLimitKeys) {
        if (const Register *reg = table.find(key))
            registers.append(reg);
    }
    if (registers.isEmpty()) {
        readFeedback(run); // a table without any of the limits: only its answers are judged
        return;
    }
    const int first = (*std::min_element(registers.begin(), registers.end(), [](auto *a, auto *b) {
                          return a->address < b->address;
                      }))->address;
    const int end = (*std::max_element(registers.begin(), registers.end(), [](auto *a, auto *b) {
                        return a->end() < b->end();
                    }))->end();
    m_bus.exchange(readExchange(servo, first, end - first),
                   [this, run, registers, first](const seriallink::TransactionResult &result,
                                                 const std::optional<Packet> &reply) {
                       if (!reply) {
                           run->reading.failure = failureText(result);
                           run->done(run->reading);
                           return;
                       }
                       HealthReading &reading = run->reading;
                       const RegisterTable &table = reading.servo.table();
                       for (const Register *reg : registers) {
                           const QByteArray bytes =
                               reply->parameters.mid(reg->address - first, reg->size);
                           if (bytes.size() != reg->size)
                               continue;
                           const qint32 raw = decodeValue(bytes, table.format(*reg));
                           const double value = raw * reg->scale;
                           if (reg->key == QLatin1String("firmware_major"))
                               reading.servo.firmwareMajor = quint8(raw);
                           else if (reg->key == QLatin1String("firmware_minor"))
                               reading.servo.firmwareMinor = quint8(raw);
                           else if (reg->key == kMinAngleLimit)
                               reading.minAngle = value;
                           else if (reg->key == kMaxAngleLimit)
                               reading.maxAngle = value;
                           else if (reg->key == QLatin1String("max_temperature"))
                               reading.maxTemperature = value;
                           else if (reg->key == QLatin1String("max_voltage"))
                               reading.maxVoltage = value;
                           else if (reg->key == QLatin1String("min_voltage"))
                               reading.minVoltage = value;
                           else if (reg->key == QLatin1String("overload_torque"))
                               reading.overloadPercent = value;
                       }
                       readFeedback(run);
                   });
}

void HealthCheck::readFeedback(std::shared_ptr<Run> run)
{
    HealthReading &reading = run->reading;
    if (reading.comm.reads == 0)
        run->before = m_bus.link().engine().counters();
    if (reading.comm.reads >= run->reads) {
        // Nothing else runs on the link during one servo's reads: the difference is its own.
        const seriallink::LinkCounters &after = m_bus.link().engine().counters();
        reading.comm.retries = after.retries - run->before.retries;
        reading.comm.timeouts = after.timeouts - run->before.timeouts;
        reading.comm.checksumErrors = after.checksumErrors - run->before.checksumErrors;
        run->done(reading);
        return;
    }
    const ServoInfo &servo = reading.servo;
    const Block block =
        servo.hasTable() ? servo.table().feedbackBlock() : Block {0, RegisterTable::kRawViewSize};
    ++reading.comm.reads;
    m_bus.exchange(
        readExchange(servo, block.address, block.size),
        [this, run](const seriallink::TransactionResult &, const std::optional<Packet> &reply) {
            if (reply) {
                HealthReading &reading = run->reading;
                ++reading.comm.answered;
                const ServoInfo &servo = reading.servo;
                if (servo.hasTable()) {
                    if (auto sample =
                            decodeFeedback(servo.table(), servo.id, servo.baud,
                                           steadyMicroseconds(), reply->parameters, reply->code))
                        reading.samples.append(*sample);
                }
            }
            if (!m_bus.link().isOpen()) {
                run->reading.failure = FeetechSessionTr::tr("The link closed.");
                run->done(run->reading);
                return;
            }
            readFeedback(run);
        });
}

} // namespace feetech
