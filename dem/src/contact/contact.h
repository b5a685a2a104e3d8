/* Contact model slots and the per-contact data the models share.
 *
 * A model is a small static inline function in its own header; pair_forces.c and walls.c
 * build one loop per combination of models, chosen once outside the loop, so a model that a
 * case does not use costs nothing there. Adding a model: a header here, an enum value, a
 * name in contact.c, and one case in the kernel table of pair_forces.c / walls.c. */
#ifndef DEM_CONTACT_H
#define DEM_CONTACT_H

enum normal_model { NORMAL_HOOKE, NORMAL_HERTZ, NORMAL_COUNT };
enum tangential_model { TANGENTIAL_NONE, TANGENTIAL_HISTORY, TANGENTIAL_COUNT };
enum cohesion_model { COHESION_NONE, COHESION_COUNT };
enum rolling_model { ROLLING_NONE, ROLLING_COUNT };
enum surface_model { SURFACE_DEFAULT, SURFACE_COUNT };

typedef struct contact_models {
    enum normal_model normal;
    enum tangential_model tangential;
    enum cohesion_model cohesion;
    enum rolling_model rolling;
    enum surface_model surface;
    double characteristic_velocity;   /* [m/s], hooke's stiffness */
    double fn_floor;                  /* 0 with limitForce (no pull from the dashpot), else -inf */
} contact_models;

extern const char *const normal_model_names[];
extern const char *const tangential_model_names[];
extern const char *const cohesion_model_names[];
extern const char *const rolling_model_names[];
extern const char *const surface_model_names[];

/* Doubles of per-contact history each model keeps (pair list and wall contacts). */
int contact_history_size(const contact_models *m);

/* What the normal model hands to the tangential one. */
typedef struct normal_result {
    double fn;       /* normal force magnitude, + repulsive [N] */
    double kt;       /* tangential stiffness [N/m] */
    double gammat;   /* tangential damping [N s/m] */
} normal_result;

#endif
