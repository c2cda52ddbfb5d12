/* swcs_book.h - the host-neutral half of a SnowWall host binding: which boundary
 * zone is what (snow / escape / none), the counts per zone, the deposit per
 * boundary face, one impact decided by the C core (sww_decide) in the wall's
 * frame, and the CSV files of an output time (doc/codesaturne.md).
 *
 * Plain C11, no host headers: the Code_Saturne binding (swcs.c) calls it from
 * cs_lagr_user_boundary_interaction; a Fluent UDF would call the same functions
 * from DEFINE_DPM_BC. No physics here: the fate and the rebound factors come
 * from sww_decide; this file only splits the velocity into its normal and
 * tangential parts and puts them back together with the core's factors.
 *
 * Every function that can fail returns SWW_OK (0) or a negative SWW_E* code
 * (sww.h) and leaves a one-line message naming the input and its value in
 * swcs_book_errmsg(). Not thread-safe (one book per host process / MPI rank).
 */
#ifndef SWCS_BOOK_H
#define SWCS_BOOK_H

#include "sww.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum { SWCS_NONE = 0, SWCS_SNOW = 1, SWCS_ESCAPE = 2 } swcs_type;

/* The type's word ("none", "snow", "escape") and back (SWW_EINVAL for any
 * other word, the message names it and the accepted words). */
const char *swcs_type_name(swcs_type t);

#define SWCS_NAME_MAX 64

/* Counts of one zone (sums over the impacts booked in this process). */
typedef struct {
    char name[SWCS_NAME_MAX];
    swcs_type type;
    long long impacts, sticks, bounces, ripoffs, escapes;
    long long outside;        /* impacts with v_n outside the map's fitted range */
    double mass_deposited;    /* [kg] */
    double mass_escaped;      /* [kg] */
} swcs_zone_counts;

typedef struct swcs_book swcs_book;

/* A book for n_faces boundary faces and zone ids 0 .. n_zones-1 (the host's
 * numbering), every zone of type none until swcs_book_set_zone. NULL when
 * out of memory or a size is 0 or above 1e9. */
swcs_book *swcs_book_alloc(size_t n_zones, size_t n_faces);
void swcs_book_free(swcs_book *b);
const char *swcs_book_errmsg(const swcs_book *b);

/* Name zone id `zone` and give it a type by its word: "snow", "escape" or
 * "none". SWW_EINVAL for an id out of range, an empty name or one longer than
 * SWCS_NAME_MAX-1, a zone set twice, or an unknown word. */
int swcs_book_set_zone(swcs_book *b, int zone, const char *name, const char *type);
swcs_type swcs_book_zone_type(const swcs_book *b, int zone);   /* NONE when out of range */
const swcs_zone_counts *swcs_book_zone(const swcs_book *b, int zone); /* NULL when out of range */
size_t swcs_book_n_zones(const swcs_book *b);
size_t swcs_book_n_faces(const swcs_book *b);
/* Deposit per face [kg] (n_faces values). */
const double *swcs_book_deposit(const swcs_book *b);

/* One impact of a particle (parcel) on face `face` of snow zone `zone`:
 *   d     diameter [m]; mass [kg] of all the particles the parcel stands for
 *   u     its velocity [m/s]; uw the wall's velocity (NULL: a wall at rest)
 *   n     the unit normal of the face, pointing out of the fluid domain
 *   tau_w wall shear stress [Pa] (read only when m's shear gate is on)
 *   rnd   a uniform random number in [0, 1), a new one per impact
 * decided by sww_decide(m); out gets the core's outcome and u_new the velocity
 * after it: 0 for a stick, uw + e_t u_t - e_n u_n n for a bounce or a rip-off
 * (u_t, u_n the parts of u - uw; a particle that moves away from the wall keeps
 * its normal part). The counts, the zone's mass and the face's deposit are
 * updated. Errors (nothing booked): SWW_EINVAL for a zone that is not snow, a
 * face out of range, a mass that is not finite and >= 0, a normal that is not a
 * unit vector (|n| - 1 beyond 1e-6), or an impact sww_decide refuses (the
 * message names d, v_n, v_t, tau_w, rnd); SWW_ENOTREADY for a model not ready. */
int swcs_book_impact(swcs_book *b, const sww_model *m, int zone, size_t face,
                     double d, double mass, const double u[3], const double uw[3],
                     const double n[3], double tau_w, double rnd,
                     sww_outcome *out, double u_new[3]);

/* A particle that leaves through escape zone `zone` (mass [kg]). SWW_EINVAL for
 * a zone that is not escape, or a mass that is not finite and >= 0. */
int swcs_book_escape(swcs_book *b, int zone, double mass);

/* Pack the counts of every zone into v (9 numbers per zone: impacts sticks
 * bounces ripoffs escapes outside mass_deposited mass_escaped 0) and set them
 * back from v (after an MPI sum over the ranks, say). n is 9 * n_zones. */
#define SWCS_PACK_PER_ZONE 9
void swcs_book_pack(const swcs_book *b, double *v);
void swcs_book_unpack(swcs_book *b, const double *v);

/* One line per snow or escape zone into buf (always terminated), e.g.
 *   SnowWall zone wall (snow): impacts 7, sticks 3, bounces 3, ripoffs 1,
 *   deposited 1.44e-12 kg (1 impacts outside the fitted v_n range)
 * (one line each, separated by '\n'). Returns the length it needed. */
size_t swcs_book_summary(const swcs_book *b, const char *prefix, char *buf, size_t n);

/* CSV of the zone counts at one output time:
 *   time,step,zone,type,impacts,sticks,bounces,ripoffs,escapes,outside,
 *   deposited_kg,escaped_kg
 * written through the common output writer (common/swo_out.h): a temporary
 * in path's folder, renamed to path once whole; path is replaced only when it
 * is absent or a regular file. SWW_EIO naming the path and the reason when it
 * cannot be written (a missing or unwritable folder, a folder, device, FIFO
 * or link at path, a full disk): the temporary is removed, path untouched.
 * No signal handler is installed (this runs inside the host process). */
int swcs_book_write_counts(swcs_book *b, const char *path, double time, long step);

/* CSV of the deposit per face of the snow zones at one output time:
 *   face,zone,x,y,z,area_m2,deposit_kg,deposit_kg_m2
 * face_num: the face's number to print (global numbering, NULL: the index);
 * cog: 3 coordinates per face; area: per face [m2]. Written as the counts. */
int swcs_book_write_deposit(swcs_book *b, const char *path, const long long *face_num,
                            const double *cog, const double *area, const int *face_zone);

#ifdef __cplusplus
}
#endif
#endif
