#pragma once

// What DevSurf's OpenCASCADE readers and writers share: OpenCASCADE's progress passed on to a
// caller's callback (and its cancel back), and its console output silenced. Included only by
// the sources built with OpenCASCADE.

#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <Message_ProgressIndicator.hxx>

#include <functional>
#include <mutex>

namespace devsurf::io {

// Reports offset + scale · (OpenCASCADE's position) to `progress`; a false answer cancels.
class OcctProgress : public Message_ProgressIndicator {
public:
    OcctProgress(const std::function<bool(double)>& progress, double offset, double scale)
        : m_progress(progress), m_offset(offset), m_scale(scale) {}
    Standard_Boolean UserBreak() override { return m_cancelled; }
    void Show(const Message_ProgressScope&, const Standard_Boolean) override {
        if (m_progress && !m_progress(m_offset + m_scale * GetPosition())) {
            m_cancelled = true;
        }
    }
    bool cancelled() const { return m_cancelled; }

private:
    const std::function<bool(double)>& m_progress;
    double m_offset;
    double m_scale;
    bool m_cancelled = false;
};

// The translators print statistics and parse errors on standard output; DevSurf reports what
// it found itself. Removes OpenCASCADE's printers once per process.
inline void quietOpenCascade() {
    static std::once_flag once;
    std::call_once(
        once, [] { Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_Printer)); });
}

} // namespace devsurf::io
