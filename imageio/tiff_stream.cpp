// The byte stream under libtiff and its message handlers (tiff_stream.h).
#include "imageio/tiff_stream.h"

#include <algorithm>
#include <cstdarg>
#include <cstring>

#include "imageio/messages.h"

namespace erd::imageio::tiff_io {

namespace {

tmsize_t stream_read(thandle_t h, void* buf, tmsize_t n) {
    Stream* s = static_cast<Stream*>(h);
    if (n <= 0) return 0;
    if (s->sink) {
        const std::size_t got = s->sink->read_at(s->pos, buf, std::size_t(n));
        s->pos += got;
        return tmsize_t(got);
    }
    if (s->file) {
        if (std::fseek(s->file, long(s->pos), SEEK_SET) != 0) return 0;
        const std::size_t got = std::fread(buf, 1, std::size_t(n), s->file);
        s->pos += got;
        return tmsize_t(got);
    }
    const std::uint64_t size = s->out ? s->out->size() : s->size;
    const unsigned char* data = s->out ? reinterpret_cast<const unsigned char*>(s->out->data()) : s->data;
    if (s->pos >= size) return 0;
    const std::uint64_t k = std::min<std::uint64_t>(std::uint64_t(n), size - s->pos);
    std::memcpy(buf, data + s->pos, std::size_t(k));
    s->pos += k;
    return tmsize_t(k);
}

tmsize_t stream_write(thandle_t h, void* buf, tmsize_t n) {
    Stream* s = static_cast<Stream*>(h);
    if (s->sink && n >= 0) {
        if (!s->sink->write_at(s->pos, buf, std::size_t(n))) return 0;
        s->pos += std::uint64_t(n);
        return n;
    }
    if (!s->out || n < 0) return 0;
    const std::uint64_t end = s->pos + std::uint64_t(n);
    if (end > s->out->size()) s->out->resize(std::size_t(end));
    std::memcpy(&(*s->out)[std::size_t(s->pos)], buf, std::size_t(n));
    s->pos = end;
    return n;
}

toff_t stream_size(thandle_t h) {
    Stream* s = static_cast<Stream*>(h);
    if (s->sink) return toff_t(s->sink->size());
    return s->out ? toff_t(s->out->size()) : toff_t(s->size);
}

toff_t stream_seek(thandle_t h, toff_t off, int whence) {
    Stream* s = static_cast<Stream*>(h);
    std::uint64_t base = 0;
    if (whence == SEEK_CUR) base = s->pos;
    else if (whence == SEEK_END) base = stream_size(h);
    s->pos = base + off;
    return s->pos;
}

int stream_close(thandle_t) { return 0; }
int stream_map(thandle_t, void**, toff_t*) { return 0; }
void stream_unmap(thandle_t, void*, toff_t) {}

int on_error(TIFF*, void* user, const char* module, const char* fmt, va_list ap) {
    Messages* m = static_cast<Messages*>(user);
    if (m && m->error.empty()) {
        char buf[512];
        std::vsnprintf(buf, sizeof buf, fmt, ap);
        std::string line = buf;
        if (module && *module && line.find(module) == std::string::npos) line = std::string(module) + ": " + line;
        for (char& c : line)
            if (c == '\n' || c == '\r') c = ' ';
        m->error = printable(line);
    }
    return 1;
}

int on_warning(TIFF*, void*, const char*, const char*, va_list) { return 1; }

}  // namespace

TIFF* open_stream(Stream* s, const char* mode, Messages* msg, std::uint64_t max_alloc) {
    TIFFOpenOptions* opts = TIFFOpenOptionsAlloc();
    if (!opts) return nullptr;
    TIFFOpenOptionsSetErrorHandlerExtR(opts, on_error, msg);
    TIFFOpenOptionsSetWarningHandlerExtR(opts, on_warning, msg);
    if (max_alloc) TIFFOpenOptionsSetMaxSingleMemAlloc(opts, tmsize_t(max_alloc));
    TIFF* tif = TIFFClientOpenExt("TIFF", mode, s, stream_read, stream_write, stream_seek, stream_close, stream_size, stream_map,
                                  stream_unmap, opts);
    TIFFOpenOptionsFree(opts);
    return tif;
}

std::string why(const Messages& m, const std::string& fallback) { return m.error.empty() ? fallback : m.error; }

int bytes_of(SampleType t) {
    switch (t) {
        case SampleType::u8: return 1;
        case SampleType::u16: case SampleType::i16: return 2;
        case SampleType::u32: case SampleType::i32: case SampleType::f32: return 4;
        case SampleType::f64: return 8;
    }
    return 1;
}

}  // namespace erd::imageio::tiff_io
