/* Stand-in for bcryptprimitives.dll, which Debian 12's Wine 8 does not ship.
 * Rust's std (1.78 and later) imports ProcessPrng from it for HashMap's RandomState and
 * any other OS randomness; without the DLL every Rust exe fails to load (status c0000135).
 * Installed into the CI Wine prefix only (.ci/windows), never shipped. */
#include <windows.h>

/* RtlGenRandom: exported by advapi32 as SystemFunction036, present in every Wine. */
BOOLEAN WINAPI SystemFunction036(PVOID buffer, ULONG length);

/* Never fails on Windows; Rust treats FALSE as fatal. Loop because RtlGenRandom takes a ULONG. */
BOOL WINAPI ProcessPrng(PBYTE data, SIZE_T len)
{
    while (len > 0) {
        ULONG chunk = len > 0x40000000 ? 0x40000000 : (ULONG)len;
        if (!SystemFunction036(data, chunk))
            return FALSE;
        data += chunk;
        len -= chunk;
    }
    return TRUE;
}

BOOL WINAPI DllMain(HINSTANCE inst, DWORD reason, LPVOID reserved)
{
    (void)inst; (void)reason; (void)reserved;
    return TRUE;
}
