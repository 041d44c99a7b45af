/* Minimal libmodbus client for the benchmark: reads REGS holding registers from address 100
 * (VW0 on a K2) with one request in flight, COUNT times or for SECONDS, and prints latency
 * figures as one JSON line. With --once it reads 10 registers, prints them and exits (the
 * one-shot measurement times the whole process).
 *
 *   mb_client tcp HOST PORT REGS COUNT SECONDS
 *   mb_client rtu PATH BAUD REGS COUNT SECONDS
 *   mb_client tcp HOST PORT --once
 */
#include <modbus.h>
#include <errno.h>
#include <string.h>
#include "common.h"

int main(int argc, char **argv) {
    if (argc < 5) {
        fprintf(stderr, "usage: %s tcp HOST PORT REGS COUNT SECONDS | rtu PATH BAUD REGS COUNT SECONDS | tcp HOST PORT --once\n", argv[0]);
        return 2;
    }
    modbus_t *ctx = strcmp(argv[1], "rtu") == 0 ? modbus_new_rtu(argv[2], atoi(argv[3]), 'N', 8, 1)
                                                 : modbus_new_tcp(argv[2], atoi(argv[3]));
    if (!ctx || modbus_set_slave(ctx, 1) != 0 || modbus_connect(ctx) != 0) {
        fprintf(stderr, "connect: %s\n", modbus_strerror(errno));
        return 1;
    }
    uint16_t regs[125];
    if (strcmp(argv[4], "--once") == 0) {
        int rc = modbus_read_registers(ctx, 100, 10, regs);
        if (rc != 10) {
            fprintf(stderr, "read: %s\n", modbus_strerror(errno));
            return 1;
        }
        for (int i = 0; i < 10; i++) printf("%u%c", regs[i], i == 9 ? '\n' : ' ');
        modbus_close(ctx);
        modbus_free(ctx);
        return 0;
    }
    int nregs = atoi(argv[4]);
    long count = atol(argv[5]);
    double secs = atof(argv[6]);
    double *lat = malloc(sizeof(double) * count);
    double start = now_s(), t = start;
    long n = 0;
    while (n < count && t - start < secs) {
        double t0 = now_s();
        if (modbus_read_registers(ctx, 100, nregs, regs) != nregs) {
            fprintf(stderr, "read: %s\n", modbus_strerror(errno));
            return 1;
        }
        t = now_s();
        lat[n++] = t - t0;
    }
    print_result(lat, n, t - start);
    modbus_close(ctx);
    modbus_free(ctx);
    return 0;
}
