// Box3D's reference figures for rbsim: one of Box3D's own benchmark scenes (erincatto/box3d
// 30c67b5, shared/benchmarks.c) stepped on one thread, timed, and its end state
// measured the way rbsim's bench/box3d_scenes.cpp measures its copy of the scene, so the two
// can be set side by side. Built by build.sh against a scalar and an SSE2 Box3D.
//   usage: pyramid_sweep --scene large_pyramid|joint_grid|column20|column40|convex_pile --substeps N --steps S [--hertz H]
//   prints: scene substeps hertz steps ms_per_step fastest_mps top_drift_m top_sink_m deepest_m
//   half_deepest_mean_m half_deepest_max_m (the deepest overlap of any contact point at the end,
//   and over the second half of the steps the mean and the worst of each step's deepest; the
//   per-step reading is outside the timed loop's figure)
//   (hertz is the world's contactHertz; Box3D's solver uses min(hertz, 0.125 / substep dt),
//   src/physics_world.c b3World_Step, so with 2 substeps at 60 Hz it is 15.)

#define _POSIX_C_SOURCE 199309L  // clock_gettime

#include "benchmarks.h"  // Box3D shared/: CreateLargePyramid, CreateJointGrid

#include "box3d/box3d.h"
#include "box3d/constants.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

// benchmark/main.c steps every scene at 1/60 s.
#define TIME_STEP ( 1.0f / 60.0f )
#define MS_PER_S 1e3
#define NS_PER_MS 1e6
#define FIRST_BODY_CAPACITY 1024  // grown by doubling

typedef struct Scene
{
	const char* name;
	void ( *create )( b3WorldId worldId );
	bool sleep;  // benchmark/main.c's world keeps sleep on; the stacking scenes' creators turn it off
} Scene;

// A column of unit cubes on Box3D's ground, as rbsim's bench/contact_scenes stacks them
// (stack20, stack40): the smallest case where the two engines part (issue 54: at 30 Hz on 4
// substeps Box3D's column of 40 stands, rbsim's of 20 topples).
#define COLUMN_HALF_EXTENT 0.5f  // [m]
#define COLUMN_DENSITY 100.0f    // [kg/m^3], the pyramid's
static void CreateColumn( b3WorldId worldId, int count )
{
	b3World_EnableSleeping( worldId, false );
	b3BodyDef groundDef = b3DefaultBodyDef();
	groundDef.position = (b3Pos){ 0.0f, -1.0f, 0.0f };  // CreateLargePyramid's ground: top at y = 0
	b3BodyId groundId = b3CreateBody( worldId, &groundDef );
	b3BoxHull ground = b3MakeBoxHull( 400.0f, 1.0f, 400.0f );
	b3ShapeDef groundShape = b3DefaultShapeDef();
	b3CreateHullShape( groundId, &groundShape, &ground.base );

	b3BodyDef bodyDef = b3DefaultBodyDef();
	bodyDef.type = b3_dynamicBody;
	b3ShapeDef shapeDef = b3DefaultShapeDef();
	shapeDef.density = COLUMN_DENSITY;
	b3BoxHull box = b3MakeBoxHull( COLUMN_HALF_EXTENT, COLUMN_HALF_EXTENT, COLUMN_HALF_EXTENT );
	for ( int i = 0; i < count; ++i )
	{
		bodyDef.position = (b3Pos){ 0.0f, ( 2.0f * i + 1.0f ) * COLUMN_HALF_EXTENT, 0.0f };
		b3BodyId bodyId = b3CreateBody( worldId, &bodyDef );
		b3CreateHullShape( bodyId, &shapeDef, &box.base );
	}
}
static void CreateColumn20( b3WorldId worldId )
{
	CreateColumn( worldId, 20 );
}
static void CreateColumn40( b3WorldId worldId )
{
	CreateColumn( worldId, 40 );
}

static const Scene scenes[] = { { "large_pyramid", CreateLargePyramid, false },
								{ "joint_grid", CreateJointGrid, false },
								{ "column20", CreateColumn20, false },
								{ "column40", CreateColumn40, false },
								{ "convex_pile", CreateConvexPile, true } };
#define SCENE_COUNT ( (int)( sizeof( scenes ) / sizeof( scenes[0] ) ) )

// Box3D has no call that lists a world's bodies, so gather them from their shapes (each body of
// these two scenes has one) with an overlap query over the whole world.
typedef struct Bodies
{
	b3BodyId* ids;
	int count, capacity;
} Bodies;

static bool CollectBody( b3ShapeId shapeId, void* context )
{
	Bodies* bodies = context;
	if ( bodies->count == bodies->capacity )
	{
		bodies->capacity = bodies->capacity > 0 ? 2 * bodies->capacity : FIRST_BODY_CAPACITY;
		bodies->ids = realloc( bodies->ids, (size_t)bodies->capacity * sizeof( b3BodyId ) );
	}
	bodies->ids[bodies->count++] = b3Shape_GetBody( shapeId );
	return true;  // go on
}

// Creation order: a new world hands out body indices 1, 2, ... as bodies are made.
static int ByIndex( const void* a, const void* b )
{
	return ( (const b3BodyId*)a )->index1 - ( (const b3BodyId*)b )->index1;
}

// The deepest overlap of any manifold point of any body's contacts (-separation, 0 if none
// overlaps), as rbsim's box3d_scenes reads Contact::manifold.maxDepth().
static double Deepest( const Bodies* bodies )
{
	double deepest = 0.0;
	b3ContactData data[256];
	for ( int i = 0; i < bodies->count; ++i )
	{
		int n = b3Body_GetContactData( bodies->ids[i], data, 256 );
		for ( int c = 0; c < n; ++c )
			for ( int m = 0; m < data[c].manifoldCount; ++m )
				for ( int p = 0; p < data[c].manifolds[m].pointCount; ++p )
					deepest = fmax( deepest, -(double)data[c].manifolds[m].points[p].separation );
	}
	return deepest;
}

static void Usage( void )
{
	fprintf( stderr, "usage: pyramid_sweep --scene large_pyramid|joint_grid|column20|column40|convex_pile --substeps N --steps S [--hertz H]\n" );
	exit( 2 );
}

int main( int argc, char** argv )
{
	const Scene* scene = NULL;
	int subSteps = 0, steps = 0;
	float hertz = -1.0f;  // < 0: Box3D's default (b3DefaultWorldDef)
	for ( int i = 1; i + 1 < argc; i += 2 )
	{
		const char* value = argv[i + 1];
		if ( strcmp( argv[i], "--scene" ) == 0 )
		{
			for ( int s = 0; s < SCENE_COUNT; ++s )
				if ( strcmp( value, scenes[s].name ) == 0 )
					scene = scenes + s;
		}
		else if ( strcmp( argv[i], "--substeps" ) == 0 )
			subSteps = atoi( value );
		else if ( strcmp( argv[i], "--steps" ) == 0 )
			steps = atoi( value );
		else if ( strcmp( argv[i], "--hertz" ) == 0 )
			hertz = (float)atof( value );
		else
			Usage();
	}
	if ( argc % 2 == 0 || scene == NULL || subSteps < 1 || steps < 1 || hertz == 0.0f )
		Usage();

	// The world as benchmark/main.c makes it for one thread: default definition, continuous on,
	// one worker (no task callbacks: src/physics_world.c b3CreateWorld then runs everything on the
	// calling thread), neither capacity function used by these two scenes. Gravity stays Box3D's
	// default (0, -10, 0) (src/types.c), y up as in rbsim. Changes asked for here: sleep off for the
	// stacking scenes (their creators turn it off too; the convex pile keeps the program's sleep)
	// and optionally the contact stiffness.
	b3WorldDef worldDef = b3DefaultWorldDef();
	worldDef.enableContinuous = true;
	worldDef.workerCount = 1;
	worldDef.enableSleep = scene->sleep;
	if ( hertz > 0.0f )
		worldDef.contactHertz = hertz;
	b3WorldId worldId = b3CreateWorld( &worldDef );
	scene->create( worldId );

	Bodies bodies = { 0 };
	b3AABB everything = { { -B3_HUGE, -B3_HUGE, -B3_HUGE }, { B3_HUGE, B3_HUGE, B3_HUGE } };
	b3World_OverlapAABB( worldId, everything, b3DefaultQueryFilter(), CollectBody, &bodies );
	qsort( bodies.ids, (size_t)bodies.count, sizeof( b3BodyId ), ByIndex );

	// The top body as rbsim picks it: the dynamic one highest at the start, the first made on a tie.
	int top = -1;
	b3Pos topStart = { 0 };
	for ( int i = 0; i < bodies.count; ++i )
	{
		if ( b3Body_GetType( bodies.ids[i] ) != b3_dynamicBody )
			continue;
		b3Pos p = b3Body_GetPosition( bodies.ids[i] );
		if ( top < 0 || p.y > topStart.y )
		{
			top = i;
			topStart = p;
		}
	}

	struct timespec t0, t1;
	double ms = 0.0, halfSum = 0.0, halfMax = 0.0;
	int halfCount = 0;
	for ( int s = 0; s < steps; ++s )
	{
		clock_gettime( CLOCK_MONOTONIC, &t0 );
		b3World_Step( worldId, TIME_STEP, subSteps );
		clock_gettime( CLOCK_MONOTONIC, &t1 );
		ms += MS_PER_S * (double)( t1.tv_sec - t0.tv_sec ) + (double)( t1.tv_nsec - t0.tv_nsec ) / NS_PER_MS;
		if ( 2 * s >= steps )
		{
			double d = Deepest( &bodies );
			halfSum += d;
			halfMax = fmax( halfMax, d );
			halfCount += 1;
		}
	}

	// End state as rbsim's box3d_scenes.cpp: the fastest dynamic body (its centre-of-mass velocity,
	// as rbsim reads RigidBody::velocity), the top body's sideways drift and its sink.
	double fastest = 0.0;
	for ( int i = 0; i < bodies.count; ++i )
	{
		if ( b3Body_GetType( bodies.ids[i] ) != b3_dynamicBody )
			continue;
		b3Vec3 v = b3Body_GetLinearVelocity( bodies.ids[i] );
		fastest = fmax( fastest, sqrt( (double)v.x * v.x + (double)v.y * v.y + (double)v.z * v.z ) );
	}
	b3Pos topNow = b3Body_GetPosition( bodies.ids[top] );
	double drift = hypot( (double)topNow.x - topStart.x, (double)topNow.z - topStart.z );
	double sink = (double)topStart.y - topNow.y;

	printf( "scene %s substeps %d hertz %g steps %d ms_per_step %.3f fastest_mps %.4f top_drift_m %.4f top_sink_m %.4f deepest_m %.4f "
			"half_deepest_mean_m %.4f half_deepest_max_m %.4f\n",
			scene->name, subSteps, (double)worldDef.contactHertz, steps, ms / steps, fastest, drift, sink, Deepest( &bodies ),
			halfSum / ( halfCount > 0 ? halfCount : 1 ), halfMax );

	free( bodies.ids );
	b3DestroyWorld( worldId );
	return 0;
}
